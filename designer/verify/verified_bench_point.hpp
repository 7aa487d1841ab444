#pragma once
// A bench point that asks for a design check verified on a full rung (BenchPoint::verify: the
// pilot hopper's B_c bracketed by DEM runs): the check with the point's settings, verified as
// `design --verify` does it, its runs kept below the point's folder (verify/: read back when
// there, a run cut short continued from its checkpoint), and the whole saved as one bench run
// (run.json) whose wall time is that of all its runs and whose commit names theirs.
#include <filesystem>

#include "designer/bench/bench_run.hpp"

namespace feedflow {

// The point's run read back from `folder`, or made and saved (`made`: a full-rung run was made,
// not only read back from the verification's kept runs); one cut short
// by Ctrl-C comes back "interrupted" and unsaved, and the same call continues it.
BenchRun run_or_read_back_verified(const BenchQuestion& question, const BenchPoint& point,
                                   const std::filesystem::path& source_root,
                                   const std::filesystem::path& folder, bool& made);

// Any point's run read back or made: a verified one as above, else run_or_read_back's.
BenchRun run_or_read_back_any(const BenchQuestion& question, const BenchPoint& point,
                              const std::filesystem::path& source_root,
                              const std::filesystem::path& folder, bool& made);

}  // namespace feedflow
