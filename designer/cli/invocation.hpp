#pragma once
// The command line feedflow was started with, for the provenance of results and reports.
#include <string>

namespace feedflow {

void record_invocation(int argc, char** argv);
const std::string& invocation();  // "feedflow design cases/pilot_hopper.toml --report"

}  // namespace feedflow
