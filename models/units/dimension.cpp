#include "models/units/dimension.hpp"

#include <array>
#include <utility>

namespace feedflow {
namespace {

struct NamedDimension {
  Dimension dimension;
  const char* name;
  const char* si;
  const char* example;
};

constexpr std::array<NamedDimension, 17> kNamed{{
    {dim::dimensionless, "dimensionless number", "", "0.5 or \"50 %\""},
    {dim::length, "length", "m", "\"60 mm\""},
    {dim::mass, "mass", "kg", "\"300 g\""},
    {dim::time, "time", "s", "\"2 s\""},
    {dim::angle, "angle", "rad", "\"30 deg\""},
    {dim::area, "area", "m^2", "\"0.01 m^2\""},
    {dim::volume, "volume", "m^3", "\"0.2 m^3\""},
    {dim::velocity, "speed", "m/s", "\"0.5 m/s\""},
    {dim::acceleration, "acceleration", "m/s^2", "\"9.81 m/s^2\""},
    {dim::angular_speed, "rotation speed", "rad/s", "\"20 rpm\""},
    {dim::rate, "rate", "1/s", "\"10 1/s\""},
    {dim::density, "density", "kg/m^3", "\"290 kg/m^3\""},
    {dim::mass_flow_rate, "mass flow rate", "kg/s", "\"2 kg/s\" or \"5 t/h\""},
    {dim::force, "force", "N", "\"10 N\""},
    {dim::pressure, "pressure or stress", "Pa", "\"187.6 kPa\""},
    {dim::energy, "energy", "J", "\"1 J\""},
    {dim::viscosity, "dynamic viscosity", "Pa*s", "\"1.8e-5 Pa*s\""},
}};

const NamedDimension* find(const Dimension& d) {
  for (const auto& n : kNamed)
    if (n.dimension == d) return &n;
  return nullptr;
}

void append_factor(std::string& out, const char* symbol, int exponent) {
  if (exponent == 0) return;
  if (!out.empty()) out += '*';
  out += symbol;
  if (exponent != 1) out += "^" + std::to_string(exponent);
}

}  // namespace

std::string si_unit(const Dimension& d) {
  if (const auto* n = find(d)) return n->si;
  // Generic form: positive exponents first, then "/" and the negative ones.
  const std::array<std::pair<const char*, int>, 4> parts{
      {{"kg", d.mass}, {"m", d.length}, {"rad", d.angle}, {"s", d.time}}};
  std::string numerator, denominator;
  for (const auto& [symbol, exponent] : parts) {
    if (exponent > 0) append_factor(numerator, symbol, exponent);
    if (exponent < 0) append_factor(denominator, symbol, -exponent);
  }
  if (numerator.empty()) numerator = "1";
  return denominator.empty() ? numerator : numerator + "/" + denominator;
}

std::string dimension_name(const Dimension& d) {
  if (const auto* n = find(d)) return n->name;
  return "quantity in " + si_unit(d);
}

std::string example_value(const Dimension& d) {
  if (const auto* n = find(d)) return n->example;
  return "\"1 " + si_unit(d) + "\"";
}

}  // namespace feedflow
