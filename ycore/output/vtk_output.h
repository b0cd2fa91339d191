// ParaView output: one compressed .vtu per frame through VTK's XML writer, and a .pvd that
// lists the frames with their times (doc/outputs.md "Files of a run").
#pragma once

#include <string>
#include <vector>

#include "ycore/state/state.h"

namespace ydry {

struct FrameSeries {
  std::string outdir, name;
  std::vector<double> times;        // s, one per frame written
  std::vector<std::string> files;   // the bulk frames, relative to outdir
};

// Writes frames/NAME_NNNNNN.vtu (the deformed bulk mesh: point data moisture,
// displacement, velocity; cell data material, moisture, and stress sxx syy sxy when the
// state has stresses), frames/NAME_cracks_NNNNNN.vtu (a line per broken joint between the
// midpoints of its end node pairs; cell data opening and slip, m, the means of the two
// ends, and moisture_face1 and moisture_face2, the mean moisture of each face's two corners,
// NaN without moisture) and rewrites NAME.pvd, which lists both per frame as parts 0 and 1.
// `cell_of_triangle`, where given ([triangles]: the fragment of each, kNoIndex for none; the
// network census's), is the bulk's cell array `cell` (-1 for none).
void write_frame(FrameSeries& series, const State& state, double time_s,
                 const std::vector<index_t>& cell_of_triangle = {});

// A restarted run's frames: those at `times` (a checkpoint's list), whose files must be in the
// folder (InputError otherwise). Frames numbered after them, which a later state of the run
// wrote, are removed, and NAME.pvd is rewritten to list these only.
void resume_frame_series(FrameSeries& series, const std::vector<double>& times);

}  // namespace ydry
