#include "fullsim/common/xdmf_point_series.hpp"

#include <cstdio>
#include <sstream>

#include "models/os/atomic_file.hpp"

namespace feedflow {
namespace {

std::string data_item(const std::string& file, const std::string& dataset, std::size_t points,
                      std::size_t components, bool floating) {
  std::ostringstream s;
  s << "<DataItem Dimensions=\"" << points;
  if (components > 1) s << ' ' << components;
  s << "\" NumberType=\"" << (floating ? "Float" : "UInt") << "\" Precision=\""
    << (floating ? 8 : 4) << "\" Format=\"HDF\">" << file << ':' << dataset << "</DataItem>";
  return s.str();
}

}  // namespace

XdmfPointSeries::XdmfPointSeries(std::filesystem::path sidecar, std::filesystem::path hdf5_file)
    : sidecar_(std::move(sidecar)) {
  const auto folder = sidecar_.parent_path();
  data_name_ = (folder.empty() ? hdf5_file : hdf5_file.lexically_relative(folder)).string();
  if (data_name_.empty()) data_name_ = hdf5_file.filename().string();
}

void XdmfPointSeries::add(XdmfPointCloud cloud) {
  clouds_.push_back(std::move(cloud));
  write_file_atomically(sidecar_, render());
}

std::string XdmfPointSeries::render() const {
  std::ostringstream s;
  s << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"2.0\">\n"
    << " <Domain>\n"
    << "  <Grid Name=\"series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& c : clouds_) {
    char time[40];
    std::snprintf(time, sizeof time, "%.17g", c.time);
    s << "   <Grid Name=\"" << c.name << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << c.points
      << "\" NodesPerElement=\"1\"/>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n"
      << "     " << data_item(data_name_, c.geometry, c.points, 3, true) << '\n'
      << "    </Geometry>\n";
    for (const auto& a : c.attributes)
      s << "    <Attribute Name=\"" << a.name << "\" AttributeType=\""
        << (a.components == 3 ? "Vector" : "Scalar") << "\" Center=\"Node\">\n"
        << "     " << data_item(data_name_, a.dataset, c.points, a.components, a.floating) << '\n'
        << "    </Attribute>\n";
    s << "   </Grid>\n";
  }
  s << "  </Grid>\n"
    << " </Domain>\n"
    << "</Xdmf>\n";
  return s.str();
}

}  // namespace feedflow
