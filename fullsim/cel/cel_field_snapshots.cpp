#include "fullsim/cel/cel_field_snapshots.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <utility>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/scene_outline.hpp"
#include "models/os/atomic_file.hpp"

namespace feedflow::cel {
namespace {

// The part of segment a-b inside the grid's box (Liang-Barsky); false when none of it is.
bool clip_to_grid(const CelGrid& g, Eigen::Vector2d& a, Eigen::Vector2d& b) {
  const Eigen::Vector2d lo = g.origin, hi = g.origin + g.cell_size * Eigen::Vector2d(g.nx, g.ny);
  const Eigen::Vector2d d = b - a;
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    for (const auto& [p, q] : {std::pair{-d[k], a[k] - lo[k]}, std::pair{d[k], hi[k] - a[k]}}) {
      if (p == 0.0) {
        if (q < 0.0) return false;
      } else if (p < 0.0) {
        t0 = std::max(t0, q / p);
      } else {
        t1 = std::min(t1, q / p);
      }
    }
  }
  if (t0 >= t1) return false;
  const Eigen::Vector2d a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

// The rigid walls present now, as segments inside the grid (end rays cut at its edge).
SceneOutline wall_outline(const CelSolver& solver) {
  const CelGrid& g = solver.grid();
  const double reach = 2.0 * g.cell_size * (g.nx + g.ny);
  SceneOutline out;
  for (const RigidWall& wall : solver.options().rigid_walls) {
    if (!wall.present(solver.time())) continue;
    const PlacedWall placed(wall, solver.time());
    const auto& pts = placed.points();
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      Eigen::Vector2d a = pts[k], b = pts[k + 1];
      const Eigen::Vector2d d = (b - a).normalized();
      if (!wall.closed && k == 0) a -= reach * d;
      if (!wall.closed && k + 2 == pts.size()) b += reach * d;
      if (clip_to_grid(g, a, b)) out.push_back({{a.x(), a.y(), 0.0}, {b.x(), b.y(), 0.0}});
    }
  }
  return out;
}

}  // namespace

CelFieldSnapshots::CelFieldSnapshots(std::filesystem::path hdf5_file, bool append)
    : file_(std::move(hdf5_file)) {
  exists_ = append && std::filesystem::exists(file_);
  if (exists_) {
    Hdf5File f(file_, Hdf5File::Mode::read);
    if (f.exists("/snapshots"))
      for (const auto& name : f.members("/snapshots")) {
        groups_.push_back("/snapshots/" + name);
        times_.push_back(f.double_attribute(groups_.back(), "time"));
      }
  }
}

std::filesystem::path CelFieldSnapshots::sidecar() const {
  auto s = file_;
  return s.replace_extension(".xdmf");
}

void CelFieldSnapshots::write(const CelSolver& solver) {
  const auto& g = solver.grid();
  const auto& c = solver.cells();
  const std::size_t n = g.cell_count();
  std::vector<double> density(n), vf(n), pressure(n), e(n), velocity(3 * n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    density[k] = c.density(k, g.cell_volume(k));
    vf[k] = c.volume_fraction[k];
    pressure[k] = vf[k] > 0.0 ? -c.stress[k].trace() / 3.0 : 0.0;
    e[k] = c.void_ratio[k];
    NodeVector v = NodeVector::Zero();
    if (vf[k] > 0.0)
      for (std::size_t a : g.cell_nodes(k)) v += 0.25 * solver.nodes().velocity[a];
    velocity[3 * k] = v.x();  // third component zero: ParaView's vectors have three
    velocity[3 * k + 1] = v.y();
  }
  char name[48];
  std::snprintf(name, sizeof name, "/snapshots/step_%09ld", solver.step_count());
  const std::string group = name;
  // The file is made with the first snapshot: a run that ends before it leaves neither file.
  Hdf5File f(file_, exists_ ? Hdf5File::Mode::append : Hdf5File::Mode::create);
  if (!exists_) {
    f.set_attribute("/", "format", std::string("feedflow CEL field snapshots"));
    f.set_attribute("/", "origin_x", g.origin.x());
    f.set_attribute("/", "origin_y", g.origin.y());
    f.set_attribute("/", "cell_size", g.cell_size);
    f.set_attribute("/", "nx", std::int64_t{g.nx});
    f.set_attribute("/", "ny", std::int64_t{g.ny});
    f.set_attribute("/", "symmetry", std::string(symmetry_name(g.symmetry)));
  }
  exists_ = true;
  if (f.exists(group)) return;  // a restart that lands on a written step
  f.create_group(group);
  f.set_attribute(group, "time", solver.time());
  f.set_attribute(group, "step", static_cast<std::int64_t>(solver.step_count()));
  const std::vector<std::size_t> dims = {static_cast<std::size_t>(g.ny), static_cast<std::size_t>(g.nx)};
  f.write(group + "/density", density, dims, "kg/m^3");
  f.write(group + "/volume_fraction", vf, dims, "1");
  f.write(group + "/pressure", pressure, dims, "Pa");
  f.write(group + "/void_ratio", e, dims, "1");
  f.write(group + "/velocity", velocity, {n, 3}, "m/s");
  write_outline(f, group + "/outline", wall_outline(solver));
  f.close();
  groups_.push_back(group);
  times_.push_back(solver.time());
  write_sidecar(g);
}

void CelFieldSnapshots::write_sidecar(const CelGrid& g) const {
  const std::string data = file_.filename().string();
  std::ostringstream s;
  s << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n"
    << " <Domain>\n  <Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  char buf[64];
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.17g", times_[k]);
    s << "   <Grid Name=\"" << groups_[k].substr(11) << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << buf << "\"/>\n"
      << "    <Topology TopologyType=\"2DCoRectMesh\" Dimensions=\"" << g.ny + 1 << ' ' << g.nx + 1
      << "\"/>\n    <Geometry GeometryType=\"ORIGIN_DXDY\">\n"
      << "     <DataItem Dimensions=\"2\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
      << g.origin.y() << ' ' << g.origin.x() << "</DataItem>\n"
      << "     <DataItem Dimensions=\"2\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
      << g.cell_size << ' ' << g.cell_size << "</DataItem>\n    </Geometry>\n";
    for (const char* a : {"density", "volume_fraction", "pressure", "void_ratio"})
      s << "    <Attribute Name=\"" << a << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "     <DataItem Dimensions=\"" << g.ny << ' ' << g.nx
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << data << ':' << groups_[k]
        << '/' << a << "</DataItem>\n    </Attribute>\n";
    s << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n"
      << "     <DataItem Dimensions=\"" << g.cell_count() << " 3\" NumberType=\"Float\" "
      << "Precision=\"8\" Format=\"HDF\">" << data << ':' << groups_[k]
      << "/velocity</DataItem>\n    </Attribute>\n   </Grid>\n";
  }
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_file_atomically(sidecar(), s.str());
}

CelFieldSnapshot read_cel_field_snapshot(const std::filesystem::path& hdf5_file,
                                         const std::string& group) {
  const Hdf5File f(hdf5_file, Hdf5File::Mode::read);
  CelFieldSnapshot s;
  try {
    s.cell_size = f.double_attribute("/", "cell_size");
  } catch (const std::runtime_error&) {
    throw std::runtime_error(hdf5_file.string() +
                             " holds no grid geometry (written by a feedflow before "
                             "snapshot files kept it)");
  }
  s.origin_x = f.double_attribute("/", "origin_x");
  s.origin_y = f.double_attribute("/", "origin_y");
  s.nx = static_cast<int>(f.integer_attribute("/", "nx"));
  s.ny = static_cast<int>(f.integer_attribute("/", "ny"));
  s.time = f.double_attribute(group, "time");
  s.step = static_cast<long>(f.integer_attribute(group, "step"));
  const std::vector<std::size_t> dims = {static_cast<std::size_t>(s.ny),
                                         static_cast<std::size_t>(s.nx)};
  s.density = f.read<double>(group + "/density", dims);
  s.volume_fraction = f.read<double>(group + "/volume_fraction", dims);
  s.pressure = f.read<double>(group + "/pressure", dims);
  s.void_ratio = f.read<double>(group + "/void_ratio", dims);
  s.velocity = f.read<double>(group + "/velocity", {dims[0] * dims[1], 3});
  s.outline = read_outline(f, group + "/outline");
  return s;
}

}  // namespace feedflow::cel
