#include "fullsim/cel/cel_field_snapshots.hpp"

#include <cstdio>
#include <sstream>

#include "fullsim/common/hdf5_file.hpp"
#include "models/os/atomic_file.hpp"

namespace feedflow::cel {

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
    density[k] = c.density(k, g.cell_volume());
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
  f.close();
  groups_.push_back(group);
  times_.push_back(solver.time());
  write_sidecar(g);
}

void CelFieldSnapshots::write_sidecar(const PlaneStrainGrid& g) const {
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

}  // namespace feedflow::cel
