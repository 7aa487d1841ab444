#pragma once
// An indexed triangle mesh [m]: welded vertices and triangles as vertex triples, as read from
// an STL file (stl_file.hpp) or built in code. Degenerate triangles (two corners at the same
// point, or collinear corners) are left out and their positions in the source listed.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

struct TriangleMesh {
  std::vector<Vec3> vertices;                          // [m], each distinct point once
  std::vector<std::array<std::uint32_t, 3>> triangles; // indices into vertices
  std::vector<std::size_t> degenerate;                 // source positions of dropped triangles
  std::string source;                                  // file name or a description

  // Adds the triangle (a, b, c), welding its corners to the vertices already present (equal
  // coordinates weld); a degenerate one is recorded under `position` instead.
  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, std::size_t position);

 private:
  std::uint32_t weld(const Vec3& x);
  std::map<std::tuple<double, double, double>, std::uint32_t> welded_;
};

}  // namespace feedflow
