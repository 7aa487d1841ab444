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
#include "models/core/time_series.hpp"

namespace feedflow {

struct HopperDischarge {
  double opening = 0.0;        // [s] on the time axis given
  double trickle_rate = 0.0;   // [kg/s] of the simulated section
  double fill_mass = 0.0;      // [kg] in the simulated section at the opening
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

}  // namespace feedflow
