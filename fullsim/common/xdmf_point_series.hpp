#pragma once
// The XDMF sidecar of a time series of point clouds stored in an HDF5 file: one Polyvertex grid
// per time, its XYZ geometry and its node attributes (scalars or vectors), all gathered in a
// temporal collection that ParaView opens (File > Open, "XDMF Reader"). The datasets are named
// relative to the sidecar's folder. The sidecar is rewritten whole after each added time
// (write_file_atomically), so a run stopped at any moment leaves a valid one.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace feedflow {

struct XdmfArray {
  std::string name;              // as ParaView shows it
  std::size_t components = 1;    // 1 (scalar) or 3 (vector)
  bool floating = true;          // Float (8 bytes) or UInt (4 bytes)
  std::string dataset;           // path inside the HDF5 file
};

struct XdmfPointCloud {
  std::string name;              // grid name
  double time = 0.0;             // [s]
  std::size_t points = 0;
  std::string geometry;          // dataset of points x 3 coordinates [m]
  std::vector<XdmfArray> attributes;
};

class XdmfPointSeries {
 public:
  // `sidecar` is the .xdmf path; `hdf5_file` the data file (named relative to the sidecar).
  XdmfPointSeries(std::filesystem::path sidecar, std::filesystem::path hdf5_file);

  // Adds a time and rewrites the sidecar.
  void add(XdmfPointCloud cloud);
  std::string render() const;
  const std::filesystem::path& path() const { return sidecar_; }
  const std::vector<XdmfPointCloud>& clouds() const { return clouds_; }

 private:
  std::filesystem::path sidecar_;
  std::string data_name_;
  std::vector<XdmfPointCloud> clouds_;
};

}  // namespace feedflow
