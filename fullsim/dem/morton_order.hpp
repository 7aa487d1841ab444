#pragma once
// Re-sorting along a Morton (Z-order) curve: particles close in space get close slots, so the
// pair loop reads neighbouring memory (fewer cache misses as the bed mixes).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fullsim/dem/simulation_box.hpp"

namespace feedflow {

// The Morton key of integer cell coordinates (21 bits each).
std::uint64_t morton_key(std::uint32_t ix, std::uint32_t iy, std::uint32_t iz);

// The slot order (new slot k holds old slot order[k]) sorting the positions by the Morton key
// of a grid of `cell` spacing over the box (ties keep their order).
std::vector<std::size_t> morton_order(const std::vector<Vec3>& positions,
                                      const SimulationBox& box, double cell);

}  // namespace feedflow
