#pragma once
// How much of a design check to build: everything a report shows (inputs, results, verdict,
// charts, assumptions), or the results and the verdict alone (a sweep's thousands of points).
namespace feedflow {

enum class DesignDetail { full, results };

}  // namespace feedflow
