#include "fullsim/dem/stl_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path, "stl", what);
}

Vec3 checked(const std::string& path, std::size_t triangle, double x, double y, double z,
             double scale) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    fail(path, "triangle " + std::to_string(triangle) + " has a non-finite vertex");
  return scale * Vec3(x, y, z);
}

void read_binary(const std::string& path, const std::string& bytes, double scale,
                 TriangleMesh& mesh) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, as STL is, on our targets
  for (std::size_t t = 0; t < count; ++t) {
    const char* rec = bytes.data() + 84 + 50 * t;
    float f[12];
    std::memcpy(f, rec, sizeof f);  // normal, then three corners
    Vec3 c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = checked(path, t, f[3 + 3 * k], f[4 + 3 * k], f[5 + 3 * k], scale);
    mesh.add_triangle(c[0], c[1], c[2], t);
  }
}

void read_ascii(const std::string& path, const std::string& bytes, double scale,
                TriangleMesh& mesh) {
  std::istringstream in(bytes);
  std::string word;
  std::size_t t = 0;
  in >> word;  // "solid"
  std::getline(in, word);  // the name
  bool ended = false;
  while (in >> word) {
    if (word == "endsolid") {
      ended = true;
      break;
    }
    if (word != "facet")
      fail(path, "ASCII: expected 'facet' or 'endsolid' before triangle " + std::to_string(t) +
                     ", found '" + word + "'");
    std::string normal;
    double nx, ny, nz;
    if (!(in >> normal >> nx >> ny >> nz) || normal != "normal")
      fail(path, "ASCII: triangle " + std::to_string(t) + ": malformed 'facet normal' line");
    std::string outer, loop;
    if (!(in >> outer >> loop) || outer != "outer" || loop != "loop")
      fail(path, "ASCII: triangle " + std::to_string(t) + ": expected 'outer loop'");
    Vec3 c[3];
    for (int k = 0; k < 3; ++k) {
      std::string vertex, sx, sy, sz;
      if (!(in >> vertex >> sx >> sy >> sz) || vertex != "vertex")
        fail(path, "ASCII: triangle " + std::to_string(t) + ": expected three 'vertex x y z' "
                   "lines (truncated or malformed)");
      double v[3];
      const std::string* s[3] = {&sx, &sy, &sz};
      for (int a = 0; a < 3; ++a) {
        char* end = nullptr;
        v[a] = std::strtod(s[a]->c_str(), &end);
        if (end == s[a]->c_str() || *end != '\0')
          fail(path, "ASCII: triangle " + std::to_string(t) + ": '" + *s[a] +
                         "' is not a number");
      }
      c[k] = checked(path, t, v[0], v[1], v[2], scale);
    }
    std::string endloop, endfacet;
    if (!(in >> endloop >> endfacet) || endloop != "endloop" || endfacet != "endfacet")
      fail(path, "ASCII: triangle " + std::to_string(t) +
                     ": expected 'endloop' and 'endfacet' (truncated or malformed)");
    mesh.add_triangle(c[0], c[1], c[2], t);
    ++t;
  }
  if (!ended) fail(path, "ASCII: no 'endsolid' (truncated file)");
}

}  // namespace

TriangleMesh read_stl(const std::string& path, double metres_per_unit) {
  if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit))
    fail(path, "the unit scale must be a positive number of metres per file unit");
  std::ifstream f(path, std::ios::binary);
  if (!f) fail(path, "cannot open the file");
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  TriangleMesh mesh;
  mesh.source = path;
  bool binary = false;
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    binary = bytes.size() == 84 + 50 * static_cast<std::size_t>(count);
  }
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string::npos && bytes.compare(first, 5, "solid") == 0;
  if (binary) {
    read_binary(path, bytes, metres_per_unit, mesh);
  } else if (says_solid && bytes.find("facet", first) != std::string::npos) {
    read_ascii(path, bytes.substr(first), metres_per_unit, mesh);
  } else if (says_solid && bytes.find("endsolid", first) != std::string::npos) {
    fail(path, "ASCII file with no triangles");
  } else if (bytes.size() < 84) {
    fail(path, "truncated: " + std::to_string(bytes.size()) +
                   " bytes, shorter than a binary STL header (84 bytes) and not ASCII STL");
  } else {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    fail(path, "binary: the header gives " + std::to_string(count) + " triangles, which need " +
                   std::to_string(84 + 50 * static_cast<std::size_t>(count)) +
                   " bytes, but the file has " + std::to_string(bytes.size()) +
                   " (truncated, or a wrong triangle count)");
  }
  if (mesh.triangles.empty())
    fail(path, "no usable triangles (" + std::to_string(mesh.degenerate.size()) + " degenerate)");
  return mesh;
}

}  // namespace feedflow
