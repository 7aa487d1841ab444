// Camera presets, the automatic fit and the projection to pixels.
#include "reports/render/camera.hpp"

#include <gtest/gtest.h>

namespace feedflow::render {
namespace {

// The front view fitted to a box puts the box centre at the image centre, shows the whole box
// with a margin, and keeps pixels square.
TEST(Camera, FrontFitFramesTheBounds) {
  Bounds3 box;
  box.include({0.0, 0.0, 0.0});
  box.include({0.4, 1.0, 0.02});
  const Camera c = fit_camera(preset_orientation(CameraPreset::front, Scene{}), box, 4.0 / 3.0);
  const ImagePoint mid = project(c, {0.2, 0.5, 0.01}, 400, 300);
  EXPECT_NEAR(mid.x, 200.0, 1e-9);
  EXPECT_NEAR(mid.y, 150.0, 1e-9);
  const ImagePoint top_left = project(c, {0.0, 1.0, 0.0}, 400, 300);
  EXPECT_GT(top_left.x, 0.0);
  EXPECT_GT(top_left.y, 0.0);  // margin above the top
  EXPECT_LT(top_left.y, 0.1 * 300);
  EXPECT_NEAR(c.half_width / c.half_height, 4.0 / 3.0, 1e-12);
  // y up in the world is up in the image; depth inside [0, 1].
  EXPECT_LT(project(c, {0.2, 0.9, 0.0}, 400, 300).y, mid.y);
  EXPECT_GT(project(c, {0.2, 0.5, 0.02}, 400, 300).depth, 0.0);
  EXPECT_LT(project(c, {0.2, 0.5, 0.0}, 400, 300).depth, 1.0);
}

// The axial view looks down the drum's axis: points along the axis share one pixel, and world
// y stays up.
TEST(Camera, AxialViewLooksDownTheDrumAxis) {
  Scene drum;
  drum.cylinders.push_back({{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.5, 2.0});  // axis along x
  const Camera oriented = preset_orientation(CameraPreset::axial, drum);
  const Camera c = fit_camera(oriented, scene_bounds(drum), 1.0);
  const ImagePoint near_end = project(c, {0.0, 0.2, 0.1}, 100, 100);
  const ImagePoint far_end = project(c, {2.0, 0.2, 0.1}, 100, 100);
  EXPECT_NEAR(near_end.x, far_end.x, 1e-9);
  EXPECT_NEAR(near_end.y, far_end.y, 1e-9);
  EXPECT_NE(near_end.depth, far_end.depth);
  EXPECT_LT(project(c, {1.0, 0.4, 0.0}, 100, 100).y, project(c, {1.0, -0.4, 0.0}, 100, 100).y);
  // The whole drum cross-section is in view.
  EXPECT_GE(c.half_height, 0.5);
}

// An empty scene still gives a usable camera.
TEST(Camera, EmptyBoundsGiveAUnitView) {
  const Camera c = fit_camera(Camera{}, Bounds3{}, 2.0);
  EXPECT_DOUBLE_EQ(c.half_height, 1.0);
  EXPECT_DOUBLE_EQ(c.half_width, 2.0);
}

}  // namespace
}  // namespace feedflow::render
