#pragma once
// HDF5 snapshots of the CEL fields, one group /snapshots/step_<step> per snapshot (time, step;
// per cell density, volume fraction, velocity (mean of the corner nodes; x, y, 0), pressure -tr T/3
// and void ratio, with their units), and an XDMF sidecar (same stem, .xdmf) with one 2DCoRectMesh
// grid per time and cell-centred attributes, which ParaView opens. The HDF5 file is closed
// after each snapshot and the sidecar rewritten atomically, so a stopped run leaves both
// readable. Appending to an existing file continues it (restart). The first snapshot also writes
// the grid (root attributes origin_x, origin_y, cell_size [m], nx, ny), and each snapshot the
// walls present then (<group>/outline, fullsim/common/scene_outline.hpp), so a picture can be
// drawn from the file alone.
#include <filesystem>
#include <string>
#include <vector>

#include "fullsim/cel/cel_solver.hpp"
#include "fullsim/common/scene_outline.hpp"

namespace feedflow::cel {

class CelFieldSnapshots {
 public:
  // `append`: keep the snapshots already in the file (a restarted run); else the first write
  // creates (truncates) the file and its sidecar.
  CelFieldSnapshots(std::filesystem::path hdf5_file, bool append);
  void write(const CelSolver& solver);
  const std::filesystem::path& file() const { return file_; }
  std::filesystem::path sidecar() const;
  std::size_t count() const { return times_.size(); }

 private:
  void write_sidecar(const CelGrid& grid) const;
  std::filesystem::path file_;
  bool exists_ = false;  // the file is there to append to
  std::vector<double> times_;
  std::vector<std::string> groups_;
};

// One snapshot read back (pictures, tests); cell k = i + nx j, as the grid numbers them.
struct CelFieldSnapshot {
  double time = 0.0;
  long step = 0;
  double origin_x = 0.0, origin_y = 0.0, cell_size = 0.0;
  int nx = 0, ny = 0;
  std::vector<double> density, volume_fraction, pressure, void_ratio;
  std::vector<double> velocity;  // 3 per cell (x, y, 0)
  SceneOutline outline;          // the walls present at this time
};
// Throws std::runtime_error naming the file when it lacks the grid (written before it was kept)
// or the group.
CelFieldSnapshot read_cel_field_snapshot(const std::filesystem::path& hdf5_file,
                                         const std::string& group);

}  // namespace feedflow::cel
