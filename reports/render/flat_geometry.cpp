#include "reports/render/flat_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reports/render/sphere_shading.hpp"

namespace feedflow::render {

FlatTriangles::FlatTriangles(const Camera& camera, double line_width)
    : camera_(camera), line_width_(line_width) {}

void FlatTriangles::push(Vec3 p, Rgb8 colour) {
  const Vec3 d = p - camera_.centre;
  vertices_.push_back({static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z),
                       colour.r, colour.g, colour.b, 255});
}

void FlatTriangles::add_triangle(Vec3 a, Vec3 b, Vec3 c, Rgb8 colour) {
  push(a, colour);
  push(b, colour);
  push(c, colour);
}

void FlatTriangles::add_line(Vec3 a, Vec3 b, Rgb8 colour) {
  // The segment's direction in the image plane; a segment seen end-on is not drawn.
  const Vec3 f = camera_.forward;
  Vec3 d = b - a;
  d = d - dot(d, f) * f;
  const double l = length(d);
  if (l < 1e-12 * std::max(1.0, camera_.half_width)) return;
  const double half = 0.5 * line_width_;
  const Vec3 along = (half / l) * d;  // square caps: extend by half the width
  const Vec3 across = half * normalised(cross(f, d));
  const Vec3 p0 = a - along - across;
  const Vec3 p1 = a - along + across;
  const Vec3 p2 = b + along + across;
  const Vec3 p3 = b + along - across;
  add_triangle(p0, p1, p2, colour);
  add_triangle(p0, p2, p3, colour);
}

void FlatTriangles::add_field_cells(const FieldGrid& field, const ColourScale& scale) {
  const double z = field.plane_z;
  for_each_filled_polygon(field, [&](int i, int j, std::span<const Point2> polygon) {
    const Rgb8 colour = scale.colour(field.value[field.index(i, j)]);
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      add_triangle({polygon[0].x, polygon[0].y, z}, {polygon[k].x, polygon[k].y, z},
                   {polygon[k + 1].x, polygon[k + 1].y, z}, colour);
    }
  });
}

void FlatTriangles::add_outline(const std::vector<OutlineSegment>& outline, double plane_z,
                                Rgb8 colour) {
  for (const OutlineSegment& s : outline) {
    add_line({s.x0, s.y0, plane_z}, {s.x1, s.y1, plane_z}, colour);
  }
}

void FlatTriangles::add_walls(const Scene& scene, Rgb8 colour) {
  for (const WallSegment& s : scene.segments) add_line(s.a, s.b, colour);
  for (const WallPlane& w : scene.planes) {
    const Vec3 c0 = w.corner;
    const Vec3 c1 = w.corner + w.edge_u;
    const Vec3 c2 = w.corner + w.edge_u + w.edge_v;
    const Vec3 c3 = w.corner + w.edge_v;
    add_line(c0, c1, colour);
    add_line(c1, c2, colour);
    add_line(c2, c3, colour);
    add_line(c3, c0, colour);
  }
  constexpr int kCircleSegments = 96;
  for (const WallCylinder& c : scene.cylinders) {
    const Vec3 axis = normalised(c.axis);
    // Two directions across the axis.
    const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 e1 = normalised(cross(axis, helper));
    const Vec3 e2 = cross(axis, e1);
    const Vec3 ends[2] = {c.base, c.base + c.length * axis};
    for (const Vec3& centre : ends) {
      for (int k = 0; k < kCircleSegments; ++k) {
        const double t0 = 2.0 * std::numbers::pi * k / kCircleSegments;
        const double t1 = 2.0 * std::numbers::pi * (k + 1) / kCircleSegments;
        add_line(centre + c.radius * (std::cos(t0) * e1 + std::sin(t0) * e2),
                 centre + c.radius * (std::cos(t1) * e1 + std::sin(t1) * e2), colour);
      }
    }
    // Silhouette lines where the shell is seen edge-on (none when looking down the axis).
    const Vec3 side = cross(axis, camera_.forward);
    if (length(side) > 1e-6) {
      const Vec3 s = c.radius * normalised(side);
      add_line(ends[0] + s, ends[1] + s, colour);
      add_line(ends[0] - s, ends[1] - s, colour);
    }
  }
}

void FlatTriangles::add_mesh(const TriangleMesh& mesh, Rgb8 colour) {
  mesh.check();
  // The sphere light, turned from camera space into the world.
  const Vec3 l = SphereShading::light();
  const Vec3 light = l.x * camera_.right() + l.y * camera_.up - l.z * camera_.forward;
  const auto vertex = [&mesh](std::uint32_t k) {
    return Vec3{mesh.positions[3 * k], mesh.positions[3 * k + 1], mesh.positions[3 * k + 2]};
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3 a = vertex(mesh.indices[t]);
    const Vec3 b = vertex(mesh.indices[t + 1]);
    const Vec3 c = vertex(mesh.indices[t + 2]);
    const Vec3 n = cross(b - a, c - a);
    const double area = length(n);
    if (area == 0.0) continue;
    const double k =
        SphereShading::ambient + SphereShading::diffuse * std::abs(dot((1.0 / area) * n, light));
    const auto channel = [k](std::uint8_t v) {
      return static_cast<std::uint8_t>(std::lround(std::min(255.0, v * k)));
    };
    add_triangle(a, b, c, {channel(colour.r), channel(colour.g), channel(colour.b)});
  }
}

}  // namespace feedflow::render
