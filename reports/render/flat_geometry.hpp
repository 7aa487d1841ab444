#pragma once
// Everything that is not a sphere, as coloured triangles built on the CPU: field cells, the
// free-surface outline, wall outlines (lines become thin quads facing the camera, since core
// OpenGL has no wide lines) and flat-shaded triangle meshes. Internal to reports/render.
#include <cstdint>
#include <vector>

#include "reports/render/camera.hpp"
#include "reports/render/colour_map.hpp"
#include "reports/render/free_surface.hpp"
#include "reports/render/scene.hpp"

namespace feedflow::render {

class FlatTriangles {
 public:
  struct Vertex {
    float x, y, z;  // relative to the camera centre
    std::uint8_t r, g, b, a;
  };

  // Lines are `line_width` metres wide.
  FlatTriangles(const Camera& camera, double line_width);

  void add_triangle(Vec3 a, Vec3 b, Vec3 c, Rgb8 colour);
  void add_line(Vec3 a, Vec3 b, Rgb8 colour);

  // The material inside the free surface, each cell in the colour of its value.
  void add_field_cells(const FieldGrid& field, const ColourScale& scale);
  void add_outline(const std::vector<OutlineSegment>& outline, double plane_z, Rgb8 colour);
  // Wall segments, plane edges, and the end circles and silhouette lines of cylinders.
  void add_walls(const Scene& scene, Rgb8 colour);
  // Triangles lit by the sphere light (both faces), flat per triangle.
  void add_mesh(const TriangleMesh& mesh, Rgb8 colour);

  const std::vector<Vertex>& vertices() const { return vertices_; }
  bool empty() const { return vertices_.empty(); }

 private:
  void push(Vec3 p, Rgb8 colour);
  Camera camera_;
  double line_width_;
  std::vector<Vertex> vertices_;
};

}  // namespace feedflow::render
