#pragma once
// The subcommands of `feedflow`. Each adds itself to the app and, when run, stores its exit
// code in `exit_code`. Errors are thrown (InputError, NotAvailable, NumericalFailure) and turned
// into messages and exit codes by main.
#include "designer/cli/command_line.hpp"

namespace feedflow {

void add_design_command(Command& program, int& exit_code);
void add_materials_command(Command& program, int& exit_code);
void add_cases_command(Command& program, int& exit_code);
void add_version_command(Command& program, int& exit_code);
void add_report_command(Command& program, int& exit_code);
// element-test: laboratory element tests of a material's hypoplastic law (CSV + JSON summary).
void add_element_test_command(Command& program, int& exit_code);
// simulate: a full simulation (DEM or CEL-FEM) of a case, results JSON and time series.
void add_simulate_command(Command& program, int& exit_code);
// bench: run time against error for every rung and setting of the seed's design questions.
void add_bench_command(Command& program, int& exit_code);
// calibrate: the reduced models' discharge coefficients fitted to a full rung.
void add_calibrate_command(Command& program, int& exit_code);
// sweep: the design check over a grid of case values (what-if analysis).
void add_sweep_command(Command& program, int& exit_code);

}  // namespace feedflow
