#pragma once
// The walls of a scene as line segments, for pictures: what a person draws around the grains or
// the continuum (the hopper's walls, the drum's shell, the chute's floor and gate), in the
// solver's own frame. Written into a run's snapshot file (a DEM run: /outline, its fixed walls
// without the gate; a CEL run: <snapshot>/outline, the walls present at that snapshot), so a
// report drawn later from the file alone shows the walls.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace feedflow {

class Hdf5File;

struct OutlineSegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  // [m]
};
using SceneOutline = std::vector<OutlineSegment>;

// A circle of `segments` chords around `centre` in the plane normal to `axis`.
SceneOutline circle_outline(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                            double radius, int segments = 96);

// Writes the dataset `path` (n x 6: the two end points of each segment [m]; nothing when empty).
void write_outline(Hdf5File& file, const std::string& path, const SceneOutline& outline);
// The outline at `path`; empty when the file has none there (a file written before outlines
// were kept).
SceneOutline read_outline(const Hdf5File& file, const std::string& path);

}  // namespace feedflow
