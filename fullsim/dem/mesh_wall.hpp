#pragma once
// A wall made of a triangle mesh (read from STL, see stl_file.hpp). A sphere touches a
// triangle's face, one of its edges or one of its corners at the closest point of the triangle
// (two-sided: the normal points from the surface to the centre). A contact shared by
// neighbouring triangles is counted once: candidates are taken nearest first, a repeated edge
// or corner is skipped, and so is an edge or corner contact whose point does not stand out of
// the tangent plane of a contact already kept (on a flat or convex patch the face contact
// stands for its neighbours; a step or a groove keeps its second contact). Triangles are
// binned on a uniform grid so a query reads only the triangles near the sphere. The mesh may
// move rigidly (velocity, angular velocity about a pivot) and be removed at a time.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "fullsim/dem/triangle_mesh.hpp"

namespace feedflow {

// One contact of a sphere with a mesh.
struct MeshTouch {
  double gap = 0.0;             // centre to the closest surface point [m]
  Vec3 normal = Vec3::UnitZ();  // unit, from the surface towards the centre
  Vec3 point = Vec3::Zero();    // the closest surface point (world) [m]
};

class MeshWall {
 public:
  static constexpr int kMaxContacts = 4;  // per sphere and mesh (a corner of a box: 3)

  MeshWall(std::string name, TriangleMesh mesh);

  // Rigid motion: translation at `velocity`, rotation at `angular_velocity` about `pivot`
  // (which moves with the mesh).
  MeshWall& moving(const Vec3& velocity, const Vec3& angular_velocity,
                   const Vec3& pivot = Vec3::Zero());
  MeshWall& removed_at(double t);

  // Writes the contacts of a sphere (centre x, radius r) into `out`, nearest first; returns
  // their number (at most kMaxContacts).
  int touches(const Vec3& x, double r, std::array<MeshTouch, kMaxContacts>& out) const;

  Vec3 surface_velocity(const Vec3& point) const {
    return velocity_ + angular_velocity_.cross(point - pivot_);
  }
  void advance(double dt);

  const std::string& name() const { return name_; }
  const TriangleMesh& mesh() const { return mesh_; }
  std::size_t triangle_count() const { return mesh_.triangles.size(); }
  const Vec3& velocity() const { return velocity_; }
  const Vec3& angular_velocity() const { return angular_velocity_; }
  bool moves() const { return velocity_.squaredNorm() > 0.0 || angular_velocity_.squaredNorm() > 0.0; }
  bool active(double t) const { return t < removal_time_; }
  std::string describe() const;

 private:
  enum Feature : std::uint8_t { face, edge, corner };
  struct Candidate {
    double gap;
    Feature kind;
    std::uint32_t id;  // triangle, edge or vertex index
    Vec3 normal, point;
  };
  void candidate(std::uint32_t t, const Vec3& x, double r, Candidate& c, bool& hit) const;

  std::string name_;
  TriangleMesh mesh_;                                   // body frame
  std::vector<Vec3> face_normal_;                       // per triangle, unit
  std::vector<Vec3> box_lower_, box_upper_;             // per triangle, its bounding box
  std::vector<std::array<std::uint32_t, 3>> edge_id_;   // per triangle: ab, bc, ca
  // Uniform grid over the body-frame bounding box; triangle t sits in the cells
  // [cell_lo_[t], cell_hi_[t]] (its own bounding box).
  Vec3 grid_lower_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::uint32_t> cell_first_, cell_triangles_;
  std::vector<std::array<int, 3>> cell_lo_, cell_hi_;
  // Pose: world = origin_ + rotation_ * body.
  bool posed_ = false;
  Vec3 origin_ = Vec3::Zero();
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
  Vec3 pivot_ = Vec3::Zero();
  Vec3 velocity_ = Vec3::Zero();
  Vec3 angular_velocity_ = Vec3::Zero();
  double removal_time_ = std::numeric_limits<double>::infinity();
};

}  // namespace feedflow
