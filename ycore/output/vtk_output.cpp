#include "ycore/output/vtk_output.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "ycore/input/input_error.h"
#include "ycore/solid/joint_law.h"
#include "ycore/output/output_files.h"

namespace ydry {
namespace {

vtkNew<vtkDoubleArray> named_array(const char* name, int components, vtkIdType tuples) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

double node_moisture(const State& s, index_t node) {
  const index_t mn = s.nodes.mnode[node];
  return mn == kNoIndex ? std::numeric_limits<double>::quiet_NaN() : s.moisture.w[mn];
}

vtkNew<vtkUnstructuredGrid> bulk_grid(const State& s, const std::vector<index_t>& cell_of_triangle) {
  const Nodes& n = s.nodes;
  const vtkIdType np = static_cast<vtkIdType>(n.size());
  const vtkIdType nt = static_cast<vtkIdType>(s.triangles.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  auto moisture = named_array("moisture", 1, np);
  auto displacement = named_array("displacement", 3, np);
  auto velocity = named_array("velocity", 3, np);
  for (vtkIdType i = 0; i < np; ++i) {
    points->SetPoint(i, n.x[i], n.y[i], 0.0);
    moisture->SetValue(i, node_moisture(s, static_cast<index_t>(i)));
    displacement->SetTuple3(i, n.x[i] - n.x0[i], n.y[i] - n.y0[i], 0.0);
    velocity->SetTuple3(i, n.vx[i], n.vy[i], 0.0);
  }
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(nt, 3 * nt);
  vtkNew<vtkIntArray> material;
  material->SetName("material");
  material->SetNumberOfTuples(nt);
  auto cell_moisture = named_array("moisture", 1, nt);
  for (vtkIdType t = 0; t < nt; ++t) {
    const vtkIdType ids[3] = {3 * t, 3 * t + 1, 3 * t + 2};
    cells->InsertNextCell(3, ids);
    material->SetValue(t, s.triangles.material[t]);
    cell_moisture->SetValue(t, (moisture->GetValue(3 * t) + moisture->GetValue(3 * t + 1) +
                                moisture->GetValue(3 * t + 2)) / 3.0);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_TRIANGLE, cells);
  grid->GetPointData()->AddArray(moisture);
  grid->GetPointData()->AddArray(displacement);
  grid->GetPointData()->AddArray(velocity);
  grid->GetCellData()->AddArray(material);
  grid->GetCellData()->AddArray(cell_moisture);
  if (s.triangles.sxx.size() == static_cast<std::size_t>(nt)) {  // a run with mechanics
    auto stress = named_array("stress", 3, nt);
    stress->SetComponentName(0, "sxx");
    stress->SetComponentName(1, "syy");
    stress->SetComponentName(2, "sxy");
    for (vtkIdType t = 0; t < nt; ++t)
      stress->SetTuple3(t, s.triangles.sxx[t], s.triangles.syy[t], s.triangles.sxy[t]);
    grid->GetCellData()->AddArray(stress);
  }
  if (cell_of_triangle.size() == static_cast<std::size_t>(nt)) {
    vtkNew<vtkIntArray> cell;
    cell->SetName("cell");
    cell->SetNumberOfTuples(nt);
    for (vtkIdType t = 0; t < nt; ++t) cell->SetValue(t, cell_of_triangle[t] == kNoIndex ? -1 : int(cell_of_triangle[t]));
    grid->GetCellData()->AddArray(cell);
  }
  return grid;
}

// One line per broken joint between the midpoints of its node pairs at the two ends, with
// the mean opening and slip of the ends, the mean moisture of each face's two corners, in
// a run with mechanics the joint's strength factor and, in a run with bonded interfaces, its
// kind (0 a material's joint, 1 an interface's).
vtkNew<vtkUnstructuredGrid> crack_grid(const State& s) {
  const Nodes& n = s.nodes;
  vtkIdType nb = 0;
  for (const std::uint8_t b : s.joints.broken) nb += b ? 1 : 0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * nb);
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(nb, 2 * nb);
  auto opening = named_array("opening", 1, nb);
  auto slip = named_array("slip", 1, nb);
  auto face1 = named_array("moisture_face1", 1, nb);  // nodes 0, 1: the first triangle's edge
  auto face2 = named_array("moisture_face2", 1, nb);  // nodes 2, 3: the second's
  const bool mechanics = s.joints.strength_factor.size() == s.joints.size();
  auto factor = named_array("strength_factor", 1, mechanics ? nb : 0);
  const bool interfaces = !s.interface_names.empty();
  auto kind = named_array("joint_kind", 1, interfaces ? nb : 0);
  vtkIdType line = 0;
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    if (!s.joints.broken[j]) continue;
    const index_t* jn = &s.joints.node[4 * j];
    for (int end = 0; end < 2; ++end) {
      const index_t a = jn[end], b = jn[3 - end];
      points->SetPoint(2 * line + end, 0.5 * (n.x[a] + n.x[b]), 0.5 * (n.y[a] + n.y[b]), 0.0);
    }
    const vtkIdType ids[2] = {2 * line, 2 * line + 1};
    cells->InsertNextCell(2, ids);
    const JointKinematics k = joint_kinematics(n, jn);
    opening->SetValue(line, 0.5 * (k.opening[0] + k.opening[1]));
    slip->SetValue(line, 0.5 * (k.slip[0] + k.slip[1]));
    face1->SetValue(line, 0.5 * (node_moisture(s, jn[0]) + node_moisture(s, jn[1])));
    face2->SetValue(line, 0.5 * (node_moisture(s, jn[2]) + node_moisture(s, jn[3])));
    if (mechanics) factor->SetValue(line, s.joints.strength_factor[j]);
    if (interfaces) kind->SetValue(line, is_interface_joint(s, j) ? 1.0 : 0.0);
    ++line;
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_LINE, cells);
  grid->GetCellData()->AddArray(opening);
  grid->GetCellData()->AddArray(slip);
  grid->GetCellData()->AddArray(face1);
  grid->GetCellData()->AddArray(face2);
  if (mechanics) grid->GetCellData()->AddArray(factor);
  if (interfaces) grid->GetCellData()->AddArray(kind);
  return grid;
}

void write_grid(vtkUnstructuredGrid* grid, const std::string& path) {
  const std::string tmp = path + ".tmp";
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(tmp.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw std::runtime_error("VTK could not write " + tmp);
  std::filesystem::rename(tmp, path);
}

// frames/NAME_NNNNNN.vtu, or frames/NAME_cracks_NNNNNN.vtu for the cracks.
std::string frame_file(const std::string& name, const char* part, std::size_t index) {
  char number[32];
  std::snprintf(number, sizeof number, "_%06zu.vtu", index);
  return "frames/" + name + part + number;
}

std::string pvd_text(const FrameSeries& series) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  char time[32];
  for (std::size_t i = 0; i < series.times.size(); ++i) {
    std::snprintf(time, sizeof time, "%.17g", series.times[i]);
    out << "    <DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << series.files[i] << "\"/>\n"
        << "    <DataSet timestep=\"" << time << "\" part=\"1\" file=\""
        << frame_file(series.name, "_cracks", i) << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace

void write_frame(FrameSeries& series, const State& state, double time_s, const std::vector<index_t>& cell_of_triangle) {
  const std::size_t index = series.times.size();
  const std::string relative = frame_file(series.name, "", index);
  write_grid(bulk_grid(state, cell_of_triangle), series.outdir + "/" + relative);
  write_grid(crack_grid(state), series.outdir + "/" + frame_file(series.name, "_cracks", index));
  series.times.push_back(time_s);
  series.files.push_back(relative);
  write_file_atomically(series.outdir + "/" + series.name + ".pvd", pvd_text(series));
}

void resume_frame_series(FrameSeries& series, const std::vector<double>& times) {
  namespace fs = std::filesystem;
  const auto path = [&](const char* part, std::size_t index) {
    return fs::path(series.outdir) / frame_file(series.name, part, index);
  };
  series.times = times;
  series.files.clear();
  for (std::size_t i = 0; i < times.size(); ++i) {
    for (const char* part : {"", "_cracks"})
      if (!fs::is_regular_file(path(part, i)))
        throw InputError(path(part, i).string() + ": a frame the checkpoint lists is missing (a restart writes into "
                                                  "the run's own output folder)");
    series.files.push_back(frame_file(series.name, "", i));
  }
  // The .pvd first: at no moment does it list a frame that is not there.
  write_file_atomically(series.outdir + "/" + series.name + ".pvd", pvd_text(series));
  for (std::size_t i = times.size(); fs::exists(path("", i)) || fs::exists(path("_cracks", i)); ++i)
    for (const char* part : {"", "_cracks"}) fs::remove(path(part, i));
}

}  // namespace ydry
