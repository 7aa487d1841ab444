#include "reports/render/free_surface.hpp"

#include <array>

namespace feedflow::render {

namespace {

// The volume fraction at the cell corners, (nx + 1) x (ny + 1), corner (a, b) at index
// a + (nx + 1) b.
std::vector<double> corner_fractions(const FieldGrid& f) {
  std::vector<double> corners(static_cast<std::size_t>(f.nx + 1) * (f.ny + 1), 0.0);
  for (int b = 0; b <= f.ny; ++b) {
    for (int a = 0; a <= f.nx; ++a) {
      double sum = 0.0;
      int count = 0;
      for (int j = b - 1; j <= b; ++j) {
        for (int i = a - 1; i <= a; ++i) {
          if (i < 0 || j < 0 || i >= f.nx || j >= f.ny) continue;
          sum += f.volume_fraction[f.index(i, j)];
          ++count;
        }
      }
      corners[static_cast<std::size_t>(a + (f.nx + 1) * b)] = sum / count;
    }
  }
  return corners;
}

// Where the contour crosses the edge from p (value vp) to q (value vq).
Point2 crossing(Point2 p, double vp, Point2 q, double vq, double level) {
  const double s = (level - vp) / (vq - vp);
  return {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)};
}

// One square of the corner grid (= one cell), classified against the level.
struct Square {
  std::array<Point2, 4> corner;  // counter-clockwise from the lower left
  std::array<bool, 4> inside{};
  std::array<Point2, 4> cut;  // edge e joins corner e to corner e + 1
  std::array<bool, 4> crossed{};
  int crossings = 0;
  bool centre_inside = false;
};

Square classify(const FieldGrid& field, const std::vector<double>& corners, int a, int b,
                double level) {
  const double h = field.cell_size;
  Square q;
  q.corner = {{{field.origin_x + a * h, field.origin_y + b * h},
               {field.origin_x + (a + 1) * h, field.origin_y + b * h},
               {field.origin_x + (a + 1) * h, field.origin_y + (b + 1) * h},
               {field.origin_x + a * h, field.origin_y + (b + 1) * h}}};
  const auto at = [&](int da, int db) {
    return corners[static_cast<std::size_t>(a + da + (field.nx + 1) * (b + db))];
  };
  const std::array<double, 4> v{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
  for (int k = 0; k < 4; ++k) q.inside[k] = v[k] >= level;
  for (int e = 0; e < 4; ++e) {
    const int f = (e + 1) % 4;
    if (q.inside[e] != q.inside[f]) {
      q.cut[e] = crossing(q.corner[e], v[e], q.corner[f], v[f], level);
      q.crossed[e] = true;
      ++q.crossings;
    }
  }
  q.centre_inside = 0.25 * (v[0] + v[1] + v[2] + v[3]) >= level;
  return q;
}

}  // namespace

std::vector<OutlineSegment> free_surface_outline(const FieldGrid& field) {
  return free_surface_outline(field, field.fill_threshold);
}

std::vector<OutlineSegment> free_surface_outline(const FieldGrid& field, double level) {
  field.check();
  const std::vector<double> corners = corner_fractions(field);
  std::vector<OutlineSegment> outline;
  for (int b = 0; b < field.ny; ++b) {
    for (int a = 0; a < field.nx; ++a) {
      const Square q = classify(field, corners, a, b, level);
      const auto emit = [&](int e0, int e1) {
        outline.push_back({q.cut[e0].x, q.cut[e0].y, q.cut[e1].x, q.cut[e1].y});
      };
      if (q.crossings == 2) {
        int first = -1;
        for (int e = 0; e < 4; ++e) {
          if (!q.crossed[e]) continue;
          if (first < 0)
            first = e;
          else
            emit(first, e);
        }
      } else if (q.crossings == 4) {
        // Saddle: cut off the two corners that the centre does not connect.
        if (q.inside[1] != q.centre_inside) {  // corners 1 and 3
          emit(0, 1);
          emit(2, 3);
        } else {  // corners 0 and 2
          emit(3, 0);
          emit(1, 2);
        }
      }
    }
  }
  return outline;
}

void for_each_filled_polygon(
    const FieldGrid& field,
    const std::function<void(int i, int j, std::span<const Point2> polygon)>& visit) {
  field.check();
  const std::vector<double> corners = corner_fractions(field);
  std::vector<Point2> polygon;
  for (int b = 0; b < field.ny; ++b) {
    for (int a = 0; a < field.nx; ++a) {
      const Square q = classify(field, corners, a, b, field.fill_threshold);
      if (q.crossings == 0) {
        if (q.inside[0]) visit(a, b, q.corner);
        continue;
      }
      if (q.crossings == 4 && !q.centre_inside) {
        // Saddle with the centre outside: two separate corner triangles.
        for (int k = 0; k < 4; ++k) {
          if (!q.inside[k]) continue;
          const Point2 triangle[3] = {q.cut[(k + 3) % 4], q.corner[k], q.cut[k]};
          visit(a, b, triangle);
        }
        continue;
      }
      // Walk the boundary: inside corners and the crossings between them.
      polygon.clear();
      for (int e = 0; e < 4; ++e) {
        if (q.inside[e]) polygon.push_back(q.corner[e]);
        if (q.crossed[e]) polygon.push_back(q.cut[e]);
      }
      visit(a, b, polygon);
    }
  }
}

}  // namespace feedflow::render
