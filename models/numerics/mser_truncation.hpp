#pragma once
// MSER truncation (White 1997) of a series of batch means: the batches to drop so that what is
// kept is steady, chosen to minimise var(kept) / kept^2. A start-up transient (a hopper opening,
// a drum's bed being lifted and overshooting) is dropped from the front; a discharge's emptying
// also from the back.
#include <cstddef>
#include <utility>
#include <vector>

namespace feedflow {

enum class MserEnds { both, front };

// The (front, back) counts to drop, each at most half the batches, leaving at least
// max(min_kept, 2); `front` only: back is 0.
std::pair<std::size_t, std::size_t> mser_truncation(const std::vector<double>& x,
                                                    std::size_t min_kept,
                                                    MserEnds ends = MserEnds::both);

}  // namespace feedflow
