#pragma once
// The Pareto front of points that cost something and miss by something (run time against
// error): a point is on the front when no other point is at least as cheap and at least as
// accurate, and strictly better in one of the two. Points with a non-finite cost or error are
// never on it.
#include <vector>

namespace feedflow {

// One flag per point, in the order given; `cost` and `error` have one value per point.
std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error);

}  // namespace feedflow
