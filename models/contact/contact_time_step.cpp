#include "models/contact/contact_time_step.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "models/core/printf_format.hpp"

namespace feedflow {
namespace {

constexpr double kPi = std::numbers::pi;

double sphere_mass(const DemParticle& p) {
  return p.density * 4.0 / 3.0 * kPi * p.radius * p.radius * p.radius;
}

// One law's springs for a contact at `overlap`, loaded and reversed once.
ContactStiffness loaded_springs(const ContactLawChoice& choice, const DemContactParameters& p,
                                const ContactInput& base, double overlap) {
  return with_contact_law(choice, [&](auto tag) {
    using Law = typename decltype(tag)::type;
    const Law law(p);
    typename Law::History h{};
    ContactInput in = base;
    in.overlap = overlap;
    in.normal_velocity = -1e-3;
    law.evaluate(in, h);
    in.overlap = overlap * (1.0 - 1e-9);
    in.normal_velocity = 1e-3;
    law.evaluate(in, h);
    in.normal_velocity = -1e-3;
    return law.stiffness(in, h);
  });
}

}  // namespace

double rayleigh_time(double radius, double density, double youngs_modulus, double poisson_ratio) {
  const double shear = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  return kPi * radius * std::sqrt(density / shear) / (0.1631 * poisson_ratio + 0.8766);
}

double hertz_collision_time(double particle_mass, double effective_radius,
                            double effective_youngs_modulus, double relative_velocity) {
  return 2.87 * std::pow(particle_mass * particle_mass /
                             (effective_radius * effective_youngs_modulus *
                              effective_youngs_modulus * relative_velocity), 0.2);
}

void StiffestSpring::consider(double period, const std::string& what) {
  if (!(period > 0.0) || !std::isfinite(period)) return;
  if (period_ == 0.0 || period < period_) {
    period_ = period;
    description_ = what;
  }
}

void StiffestSpring::add(const ContactStiffness& k, double effective_mass,
                         double effective_inertia, double overlap, std::string_view where) {
  const std::string at = format(" at overlap %.3g m", overlap);
  const std::string w(where);
  if (k.normal > 0.0)
    consider(2.0 * kPi * std::sqrt(effective_mass / k.normal),
             format("%s normal spring %.3g N/m", w.c_str(), k.normal) + at);
  if (k.tangential > 0.0)
    consider(2.0 * kPi * std::sqrt(2.0 / 7.0 * effective_mass / k.tangential),
             format("%s tangential spring %.3g N/m", w.c_str(), k.tangential) + at);
  if (k.rolling > 0.0)
    consider(2.0 * kPi * std::sqrt(effective_inertia / k.rolling),
             format("%s rolling spring %.3g N m/rad", w.c_str(), k.rolling) + at);
}

namespace {

StiffestSpring springs_at(const DemParameters& dem, const ContactLawChoice& particle_particle,
                          const ContactLawChoice& particle_wall, double pp_ratio,
                          double pw_ratio) {
  const double r = dem.particle.radius;
  const double m = sphere_mass(dem.particle);
  const double inertia = 0.4 * m * r * r;
  StiffestSpring springs;
  ContactInput pp;
  pp.effective_radius = r / 2;
  pp.effective_mass = m / 2;
  pp.effective_inertia = inertia / 2;
  pp.dt = 1e-6;
  if (pp_ratio > 0.0)
    springs.add(loaded_springs(particle_particle, dem.particle_particle, pp, pp_ratio * r), m / 2,
                inertia / 2, pp_ratio * r, "P-P");
  ContactInput pw = pp;
  pw.effective_radius = r;
  pw.effective_mass = m;
  pw.effective_inertia = inertia;
  if (pw_ratio > 0.0)
    springs.add(loaded_springs(particle_wall, dem.particle_wall, pw, pw_ratio * r), m, inertia,
                pw_ratio * r, "P-W");
  return springs;
}

}  // namespace

StiffestSpring design_springs(const DemParameters& dem, const ContactLawChoice& particle_particle,
                              const ContactLawChoice& particle_wall, double design_overlap) {
  return springs_at(dem, particle_particle, particle_wall, design_overlap, design_overlap);
}

StiffestSpring current_springs(const DemParameters& dem, const ContactLawChoice& law,
                               double particle_particle_ratio, double particle_wall_ratio) {
  return springs_at(dem, law, law, particle_particle_ratio, particle_wall_ratio);
}

StableTimeStep stable_time_step(const DemParameters& dem, const StiffestSpring& springs,
                                const TimeStepSettings& settings) {
  const auto& p = dem.particle_particle;
  const double r = dem.particle.radius;
  const double t_r = rayleigh_time(r, dem.particle.density, p.youngs_modulus, p.poisson_ratio);
  const double t_h =
      hertz_collision_time(sphere_mass(dem.particle), r / 2,
                           effective_youngs_modulus(p.youngs_modulus, p.poisson_ratio),
                           2.0 * settings.max_velocity);
  const double dt_r = settings.rayleigh_fraction * t_r;
  const double dt_h = settings.hertz_fraction * t_h;
  const double dt_s = springs.empty() ? 0.0 : springs.period() / settings.steps_per_period;
  StableTimeStep out;
  const std::string rayleigh = format("%g T_R = %.3g s", settings.rayleigh_fraction, dt_r);
  const std::string hertz = format("%g t_H = %.3g s (v_max %g m/s)", settings.hertz_fraction,
                                   dt_h, settings.max_velocity);
  const std::string spring =
      springs.empty() ? std::string("no spring")
                      : format("period %.3g s / %g = %.3g s", springs.period(),
                               settings.steps_per_period, dt_s) +
                            " (" + springs.description() + ")";
  if (dt_s > 0.0 && dt_s <= dt_r && dt_s <= dt_h) {
    out.value = dt_s;
    out.justification = format("dt = %.3g s from the stiffest spring: ", dt_s) + spring +
                           "; Rayleigh " + rayleigh + ", Hertz " + hertz;
  } else if (dt_r <= dt_h) {
    out.value = dt_r;
    out.justification = format("dt = %.3g s from the Rayleigh time: ", dt_r) + rayleigh +
                        "; Hertz " + hertz + ", spring " + spring;
  } else {
    out.value = dt_h;
    out.justification = format("dt = %.3g s from the Hertz collision time: ", dt_h) + hertz +
                        "; Rayleigh " + rayleigh + ", spring " + spring;
  }
  return out;
}

}  // namespace feedflow
