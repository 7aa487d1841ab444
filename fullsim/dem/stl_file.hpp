#pragma once
// Reads an STL file (binary or ASCII) into a welded TriangleMesh. STL carries no unit: the
// caller gives the metres per file unit (1 for metres, 1e-3 for millimetres). Binary is
// recognised by its size (84 + 50 n bytes for the n triangles of its header), so a binary file
// whose header starts with "solid" is still read as binary. Throws InputError naming the file
// and the fault: unreadable, truncated, triangle count not matching the size, a malformed or
// non-finite vertex, no triangles left. Degenerate triangles are dropped and listed in
// TriangleMesh::degenerate.
#include <string>

#include "fullsim/dem/triangle_mesh.hpp"

namespace feedflow {

TriangleMesh read_stl(const std::string& path, double metres_per_unit);

}  // namespace feedflow
