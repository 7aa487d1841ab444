#include "reports/render/snapshot_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace feedflow::render {

SnapshotLayout snapshot_layout(int width, int height, bool with_legend, bool with_colour_bar) {
  if (width < 16 || height < 16) {
    throw std::invalid_argument("snapshot of " + std::to_string(width) + "x" +
                                std::to_string(height) + " pixels: at least 16x16 needed");
  }
  SnapshotLayout layout;
  layout.font_size = std::clamp(height / 50.0, 8.0, 28.0);
  const double f = layout.font_size;
  if (!with_legend) {
    layout.scene = {0, 0, width, height};
    return layout;
  }
  const int panel =
      std::min(width / 3, static_cast<int>(std::lround(std::max(9.0 * f, 0.15 * width))));
  layout.scene = {0, 0, width - panel, height};
  layout.legend = {width - panel, 0, panel, height};
  if (with_colour_bar) {
    // Title (two lines) above, the bar below it, tick labels to its right.
    const int top = static_cast<int>(std::lround(3.5 * f));
    const int bottom = static_cast<int>(std::lround(1.5 * f));
    layout.colour_bar = {
        layout.legend.x + static_cast<int>(std::lround(1.0 * f)), top,
        std::max(4, static_cast<int>(std::lround(1.1 * f))),
        std::max(8, std::min(height - top - bottom, static_cast<int>(std::lround(0.65 * height))))};
  }
  return layout;
}

}  // namespace feedflow::render
