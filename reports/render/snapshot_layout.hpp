#pragma once
// Where things go on a snapshot: the scene on the left, a legend panel on the right (when there
// is a colour bar or a layer legend), the scale bar in the scene's lower-left corner. Sizes
// follow the image height so a 1600 x 1200 snapshot and a 320 x 240 thumbnail look alike.
namespace feedflow::render {

// Pixels [x, x + width) x [y, y + height), y downwards.
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  bool contains(int px, int py) const {
    return px >= x && px < x + width && py >= y && py < y + height;
  }
};

struct SnapshotLayout {
  PixelRect scene;
  PixelRect legend;         // empty (width 0) without a legend
  PixelRect colour_bar;     // the gradient itself, inside `legend`; empty without a colour bar
  double font_size = 12.0;  // pixels
};

// Throws std::invalid_argument for an image smaller than 16 x 16 pixels.
SnapshotLayout snapshot_layout(int width, int height, bool with_legend, bool with_colour_bar);

}  // namespace feedflow::render
