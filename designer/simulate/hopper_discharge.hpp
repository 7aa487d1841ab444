#pragma once
// The discharge of a hopper run measured the same way on both full rungs (the DEM's sink and
// the CEL's outflow ledger, sampled into the run's series; fullsim/common/
// discharge_measurement.hpp): the steady rate over batches of 50 ms (at least five kept), when
// the run may stop (the rate's 95 % interval within +-5 % over ten batches at least, or the
// discharge has arched or emptied), and the discharge state with the trickle at 2 % of the
// outlet's scale rate rho_b W sqrt(g W) over the section the run simulates.
#include <string>
#include <vector>

#include "fullsim/common/discharge_measurement.hpp"
#include "fullsim/common/flow_pattern_measurement.hpp"
#include "models/core/design_record.hpp"
#include "models/core/time_series.hpp"

namespace feedflow {

struct HopperDischarge {
  double opening = 0.0;        // [s] on the time axis given
  double trickle_rate = 0.0;   // [kg/s] of the simulated section
  std::string scale_rate = "rho_b W sqrt(g W)";  // the outlet's scale rate in words (a slot's)
  double fill_mass = 0.0;      // [kg] in the simulated section at the opening
  // "converged" is not said before this long after the opening [s] (the CEL cone's rate still
  // climbs for about a second after it; 0: whenever the interval is narrow enough).
  double earliest_convergence = 0.0;
  ArchCriterion arch{};

  // One cumulative discharge: times and masses of the rows after the opening, with the state
  // of the last row.
  struct Rows {
    std::vector<double> time, discharged;  // [s], [kg]
    double kinetic_energy = 0.0;           // [J] at the last row
    double mass_left = 0.0;                // [kg] at the last row
  };

  SteadyRate steady_rate(const Rows& rows) const;
  DischargeState state(const Rows& rows) const;
  // "converged: ...", "arched: ...", "the hopper has emptied", or empty (run on).
  std::string stop_reason(const Rows& rows) const;
  // The arching rule in words, with its numbers.
  std::string describe() const;
};

// The rows of `series` from its columns: time, discharged mass, mass in the domain, kinetic
// energy.
HopperDischarge::Rows discharge_rows(const TimeSeries& series, std::size_t time, std::size_t discharged,
                                    std::size_t mass_left, std::size_t kinetic_energy);

// How one rung words and scales the discharge results.
struct DischargeWording {
  Rung rung = Rung::L3;
  double scale = 1.0;          // simulated section -> the whole hopper
  std::string rate_source;     // the rate's source, before "; steady window ..." or the arch
  std::string steady_detail;   // appended to the steady rate's source after the window
  std::string arched_detail;   // appended to the zero rate's source when arched
  std::string model;           // the arching source, before "; " and the rule
  std::string pattern_source;  // the flow pattern's source
  std::string speeds;          // what the flow line samples ("particle speeds", "node speeds")
  double pattern_from = 0.0;   // [s] the flow line's average starts here without a steady window
};

// The discharge results of a hopper run, the same on every rung: mass_flow_rate (0 when
// arched, else the steady rate scaled to the hopper, else a note to run longer), arching, and
// unless arched the flow pattern with the wall-to-centre speed ratio over the steady window.
// Returns the steady rate (in the simulated section) for the rung's own extra rows.
SteadyRate add_discharge_results(const HopperDischarge& d, const HopperDischarge::Rows& rows,
                                 const SpeedProfileSeries& flow_line, const DischargeWording& w,
                                 DesignRecord& record);

}  // namespace feedflow
