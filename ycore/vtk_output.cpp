#include "ycore/vtk_output.h"

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

#include "ycore/output_files.h"

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

vtkNew<vtkUnstructuredGrid> bulk_grid(const State& s) {
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

std::string pvd_text(const FrameSeries& series) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  char time[32];
  for (std::size_t i = 0; i < series.times.size(); ++i) {
    std::snprintf(time, sizeof time, "%.17g", series.times[i]);
    out << "    <DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << series.files[i] << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace

void write_frame(FrameSeries& series, const State& state, double time_s) {
  char file[64];
  std::snprintf(file, sizeof file, "_%06zu.vtu", series.times.size());
  const std::string relative = "frames/" + series.name + file;
  write_grid(bulk_grid(state), series.outdir + "/" + relative);
  series.times.push_back(time_s);
  series.files.push_back(relative);
  write_file_atomically(series.outdir + "/" + series.name + ".pvd", pvd_text(series));
}

}  // namespace ydry
