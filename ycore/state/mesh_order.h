// The triangles' numbering, chosen for the threads (doc/threading.md "Ownership slots").
#pragma once

#include "ycore/state/mesh_input.h"

namespace ydry {

// Renumbers the triangles in the order of their centroids along a Hilbert curve, so that
// triangles near in the numbering are near in the mesh.
void order_triangles_along_hilbert_curve(MeshInput& mesh);

}  // namespace ydry
