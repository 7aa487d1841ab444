#include "fullsim/cel/cel_scene.hpp"

#include <cstdio>

namespace feedflow::cel {

std::string grid_text(const CelGrid& g) {
  char text[160];
  std::snprintf(text, sizeof text, "h = %.3g mm, %d x %d cells (%.3g m x %.3g m)",
                g.cell_size * 1e3, g.nx, g.ny, g.nx * g.cell_size, g.ny * g.cell_size);
  return text;
}

}  // namespace feedflow::cel
