#include "fullsim/dem/mesh_wall.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "fullsim/dem/wall.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

MeshWall::MeshWall(std::string name, TriangleMesh mesh) : name_(std::move(name)), mesh_(std::move(mesh)) {
  if (mesh_.triangles.empty()) throw InputError(mesh_.source, "wall." + name_, "mesh has no triangles");
  const std::size_t nt = mesh_.triangles.size();
  face_normal_.resize(nt);
  box_lower_.resize(nt);
  box_upper_.resize(nt);
  edge_id_.resize(nt);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edges;
  Vec3 lower = mesh_.vertices[0], upper = lower;
  for (const Vec3& v : mesh_.vertices) {
    lower = lower.cwiseMin(v);
    upper = upper.cwiseMax(v);
  }
  double extent_sum = 0.0;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = mesh_.triangles[t];
    const Vec3 &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
    face_normal_[t] = (b - a).cross(c - a).normalized();
    box_lower_[t] = a.cwiseMin(b).cwiseMin(c);
    box_upper_[t] = a.cwiseMax(b).cwiseMax(c);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = tri[k], j = tri[(k + 1) % 3];
      const auto key = std::minmax(i, j);
      const auto [it, added] = edges.emplace(key, static_cast<std::uint32_t>(edges.size()));
      edge_id_[t][k] = it->second;
    }
    // The triangle's middle extent over the axes: a long strip (a saw-tooth ramp's face across
    // a slab, 45 mm by 2 mm) counts by its width, so its cells stay about a tooth wide instead
    // of a slab, where each query would read every tooth.
    Vec3 e = a.cwiseMax(b).cwiseMax(c) - a.cwiseMin(b).cwiseMin(c);
    std::sort(e.data(), e.data() + 3);
    extent_sum += e[1];
  }
  // Cells about the mean triangle size, at most 256 along the longest side and 4 M in all.
  const Vec3 extent = upper - lower;
  cell_ = std::max({extent_sum / static_cast<double>(nt), extent.maxCoeff() / 256.0, 1e-9});
  auto count = [&] {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a) {
      dims_[a] = static_cast<int>(std::floor(extent[a] / cell_)) + 1;
      cells *= dims_[a];
    }
    return cells;
  };
  while (count() > 4e6) cell_ *= 2.0;
  grid_lower_ = lower;
  auto cell_of = [&](const Vec3& x, std::array<int, 3>& c) {
    for (int a = 0; a < 3; ++a)
      c[a] = std::clamp(static_cast<int>(std::floor((x[a] - lower[a]) / cell_)), 0, dims_[a] - 1);
  };
  cell_lo_.resize(nt);
  cell_hi_.resize(nt);
  const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  std::vector<std::uint32_t> fill(cells + 1, 0);
  auto each_cell = [&](std::size_t t, auto&& visit) {
    for (int k = cell_lo_[t][2]; k <= cell_hi_[t][2]; ++k)
      for (int j = cell_lo_[t][1]; j <= cell_hi_[t][1]; ++j)
        for (int i = cell_lo_[t][0]; i <= cell_hi_[t][0]; ++i)
          visit((static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i);
  };
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = mesh_.triangles[t];
    const Vec3 &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
    cell_of(a.cwiseMin(b).cwiseMin(c), cell_lo_[t]);
    cell_of(a.cwiseMax(b).cwiseMax(c), cell_hi_[t]);
    each_cell(t, [&](std::size_t cell) { ++fill[cell + 1]; });
  }
  for (std::size_t i = 0; i < cells; ++i) fill[i + 1] += fill[i];
  cell_first_ = fill;
  cell_triangles_.resize(fill[cells]);
  for (std::size_t t = 0; t < nt; ++t)
    each_cell(t, [&](std::size_t cell) { cell_triangles_[fill[cell]++] = static_cast<std::uint32_t>(t); });
}

MeshWall& MeshWall::moving(const Vec3& velocity, const Vec3& angular_velocity, const Vec3& pivot) {
  velocity_ = velocity;
  angular_velocity_ = angular_velocity;
  pivot_ = pivot;
  return *this;
}

MeshWall& MeshWall::removed_at(double t) {
  removal_time_ = t;
  return *this;
}

void MeshWall::advance(double dt) {
  if (!moves()) return;
  posed_ = true;
  const Vec3 pivot = pivot_ + dt * velocity_;
  const double turn = angular_velocity_.norm() * dt;
  Eigen::Matrix3d q = Eigen::Matrix3d::Identity();
  if (turn > 0.0) q = Eigen::AngleAxisd(turn, angular_velocity_.normalized()).toRotationMatrix();
  origin_ = pivot + q * (origin_ - pivot_);
  rotation_ = q * rotation_;
  pivot_ = pivot;
}

// The closest point of triangle t to x (Ericson, Real-Time Collision Detection 5.1.5), with
// the feature it lies on.
void MeshWall::candidate(std::uint32_t t, const Vec3& x, double r, Candidate& out, bool& hit) const {
  hit = false;
  const auto& tri = mesh_.triangles[t];
  const Vec3 &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
  const Vec3& n = face_normal_[t];
  const double s = (x - a).dot(n);
  if (std::abs(s) >= r) return;  // the plane is out of reach
  auto at_point = [&](Feature kind, std::uint32_t id, const Vec3& p) {
    const Vec3 d = x - p;
    const double g = d.norm();
    if (!(g < r)) return;
    out.kind = kind;
    out.id = id;
    out.point = p;
    out.gap = g;
    out.normal = g > 0.0 ? Vec3(d / g) : Vec3(s >= 0.0 ? n : Vec3(-n));
    hit = true;
  };
  const Vec3 ab = b - a, ac = c - a, ap = x - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at_point(corner, tri[0], a);
  const Vec3 bp = x - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return at_point(corner, tri[1], b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at_point(edge, edge_id_[t][0], a + (d1 / (d1 - d3)) * ab);
  const Vec3 cp = x - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return at_point(corner, tri[2], c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at_point(edge, edge_id_[t][2], a + (d2 / (d2 - d6)) * ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return at_point(edge, edge_id_[t][1], b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  // Inside the face: the distance to the plane, as for an analytic plane.
  out.kind = face;
  out.id = t;
  out.gap = std::abs(s);
  out.normal = s >= 0.0 ? n : Vec3(-n);
  out.point = x - s * n;
  hit = true;
}

int MeshWall::touches(const Vec3& x_world, double r, std::array<MeshTouch, kMaxContacts>& result) const {
  const Vec3 x = posed_ ? Vec3(rotation_.transpose() * (x_world - origin_)) : x_world;
  std::array<int, 3> lo, hi;
  for (int a = 0; a < 3; ++a) {
    const double l = std::floor((x[a] - r - grid_lower_[a]) / cell_);
    const double h = std::floor((x[a] + r - grid_lower_[a]) / cell_);
    if (h < 0.0 || l >= dims_[a]) return 0;
    lo[a] = std::max(0, static_cast<int>(l));
    hi[a] = std::min(dims_[a] - 1, static_cast<int>(h));
  }
  constexpr int kCapacity = 64;
  std::array<Candidate, kCapacity> found;
  int nfound = 0;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t cell = (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
        for (std::uint32_t e = cell_first_[cell]; e < cell_first_[cell + 1]; ++e) {
          const std::uint32_t t = cell_triangles_[e];
          // A triangle spanning several cells is read in the first cell it shares with the query.
          const auto &tl = cell_lo_[t];
          if (i != std::max(tl[0], lo[0]) || j != std::max(tl[1], lo[1]) || k != std::max(tl[2], lo[2]))
            continue;
          // Out of reach of the triangle's box, out of reach of the triangle: no contact.
          const Vec3 out = (box_lower_[t] - x).cwiseMax(x - box_upper_[t]).cwiseMax(0.0);
          if (out.squaredNorm() >= r * r) continue;
          Candidate c;
          bool hit = false;
          candidate(t, x, r, c, hit);
          if (!hit) continue;
          if (nfound < kCapacity) {
            found[nfound++] = c;
          } else {  // keep the nearest
            auto worst = std::max_element(found.begin(), found.end(),
                                          [](const Candidate& p, const Candidate& q) { return p.gap < q.gap; });
            if (c.gap < worst->gap) *worst = c;
          }
        }
      }
  std::sort(found.begin(), found.begin() + nfound, [](const Candidate& p, const Candidate& q) {
    return p.gap != q.gap ? p.gap < q.gap : p.kind < q.kind;
  });
  const double tolerance = 1e-9 * r;
  int kept = 0;
  std::array<const Candidate*, kMaxContacts> keep{};
  for (int f = 0; f < nfound && kept < kMaxContacts; ++f) {
    const Candidate& c = found[f];
    bool shadowed = false;
    for (int q = 0; q < kept && !shadowed; ++q) {
      const Candidate& k = *keep[q];
      shadowed = (c.kind == k.kind && c.id == k.id) ||
                 (c.point - k.point).dot(k.normal) <= tolerance;
    }
    if (!shadowed) keep[kept++] = &c;
  }
  for (int q = 0; q < kept; ++q) {
    MeshTouch& m = result[q];
    m.gap = keep[q]->gap;
    m.normal = posed_ ? Vec3(rotation_ * keep[q]->normal) : keep[q]->normal;
    m.point = posed_ ? Vec3(origin_ + rotation_ * keep[q]->point) : keep[q]->point;
  }
  return kept;
}

std::string MeshWall::describe() const {
  char buf[512];
  std::snprintf(buf, sizeof buf, "mesh '%s' from %s: %zu triangles, %zu vertices (%zu degenerate dropped), grid %dx%dx%d of %.4g m",
                name_.c_str(), mesh_.source.empty() ? "code" : mesh_.source.c_str(), mesh_.triangles.size(),
                mesh_.vertices.size(), mesh_.degenerate.size(), dims_[0], dims_[1], dims_[2], cell_);
  std::string s = buf;
  return s + wall_motion_text(velocity_, angular_velocity_, removal_time_);
}

}  // namespace feedflow
