// Meshes from Gmsh (mesh.file).
#pragma once

#include <istream>
#include <string>

#include "ycore/state/mesh_input.h"

namespace ydry {

// Gmsh 4.1 ASCII reader: 3-node triangles in physical surfaces (the surface's name is the
// material), 2-node lines in physical curves (each curve name is a boundary). Throws
// InputError naming the file and line on anything it cannot represent.
MeshInput read_gmsh(const std::string& path);
// The same from a stream; `path` names it in messages.
MeshInput read_gmsh(std::istream& in, const std::string& path);

}  // namespace ydry
