#pragma once
// Field snapshots of a run, written by the engine that owns the fields (DEM particles, CEL
// cells) into an HDF5 file with an XDMF sidecar, which ParaView opens. The scene run loop
// decides when; the writer decides how.
#include <filesystem>
#include <vector>

namespace feedflow {

class SnapshotWriter {
 public:
  virtual ~SnapshotWriter() = default;
  // A snapshot of the engine's state now; none when one was already written at this time.
  virtual void write() = 0;
  virtual std::size_t count() const = 0;
  // The files written so far (HDF5 and sidecar); empty before the first snapshot.
  virtual std::vector<std::filesystem::path> files() const = 0;
};

}  // namespace feedflow
