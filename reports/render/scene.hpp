#pragma once
// What a snapshot shows, as plain data: no solver types. A solver (or a test) fills a Scene;
// the renderer draws it. All lengths in metres, in the frame of vec3.hpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "reports/render/vec3.hpp"

namespace feedflow::render {

// Spheres as a structure of arrays: particle i is at (x[i], y[i], z[i]) with radius[i].
// `value` (one scalar per particle, e.g. speed) and `layer` (initial layer id, >= 0) are
// optional: empty, or one entry per particle.
struct ParticleSet {
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> z;
  std::vector<double> radius;
  std::vector<double> value;
  std::vector<std::int32_t> layer;

  std::size_t size() const { return x.size(); }
  // Throws std::invalid_argument when the arrays disagree in length or a radius is not
  // positive and finite.
  void check() const;
};

// A continuum result on a uniform 2-D grid of square cells lying in the plane z = plane_z.
// Cell (i, j), i along x and j along y, covers [origin_x + i h, origin_x + (i+1) h] x
// [origin_y + j h, ...] with h = cell_size; its data sit at index i + nx * j. Cells whose
// volume fraction is below `fill_threshold` are void and not drawn; the free surface is the
// `fill_threshold` contour of the volume fraction.
struct FieldGrid {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double plane_z = 0.0;
  double cell_size = 0.0;
  int nx = 0;
  int ny = 0;
  std::vector<double> value;
  std::vector<double> volume_fraction;
  double fill_threshold = 0.5;

  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i + nx * j); }
  // Throws std::invalid_argument for a non-positive cell size or arrays of the wrong size.
  void check() const;
};

// Walls, drawn as outlines: a straight edge, a finite plane (the parallelogram corner +
// s edge_u + t edge_v, s and t in [0, 1]) and a cylinder (a drum shell: the axis runs from
// `base` along the unit vector `axis` for `length`).
struct WallSegment {
  Vec3 a;
  Vec3 b;
};
struct WallPlane {
  Vec3 corner;
  Vec3 edge_u;
  Vec3 edge_v;
};
struct WallCylinder {
  Vec3 base;
  Vec3 axis{0.0, 0.0, 1.0};
  double radius = 0.0;
  double length = 0.0;
};

// A triangle mesh (an insert, a discharge screw): vertex k at positions[3k .. 3k+2];
// triangle t joins the vertices indices[3t .. 3t+2].
struct TriangleMesh {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;

  // Throws std::invalid_argument for a ragged array or an index out of range.
  void check() const;
};

struct Scene {
  ParticleSet particles;
  std::optional<FieldGrid> field;
  std::vector<WallSegment> segments;
  std::vector<WallPlane> planes;
  std::vector<WallCylinder> cylinders;
  std::vector<TriangleMesh> meshes;
};

// An axis-aligned box; empty until something is included.
struct Bounds3 {
  Vec3 lo{1.0, 1.0, 1.0};
  Vec3 hi{-1.0, -1.0, -1.0};

  bool empty() const { return lo.x > hi.x; }
  // Grows the box to hold the ball of radius `pad` around `p`.
  void include(Vec3 p, double pad = 0.0);
};

// The bounds of everything drawn: spheres with their radii, the whole field grid, walls and
// meshes.
Bounds3 scene_bounds(const Scene& scene);

}  // namespace feedflow::render
