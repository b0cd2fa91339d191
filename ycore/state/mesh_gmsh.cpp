// Gmsh MSH 4.1 ASCII reader (see mesh_gmsh.h). Keeps node x, y; 3-node triangles with the
// name of their physical surface as material; 2-node lines under each name of their physical
// curves. Unused sections are skipped; anything else it cannot represent is an InputError
// naming the file and line.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "ycore/input/input_error.h"
#include "ycore/state/mesh_gmsh.h"

namespace ydry {
namespace {

// The file being read and its line last read (1-based number, text without trailing blanks).
struct MshFile {
  std::string path;
  std::istream& in;
  long line = 0;
  std::string text;
};

// What the sections before $Elements say about the entities and nodes.
struct MshModel {
  std::map<std::pair<int, int>, std::string> physical_names;           // (dim, tag) -> name
  std::map<int, std::vector<int>> curve_physicals, surface_physicals;  // entity -> physical tags
  std::unordered_map<long long, index_t> vertex_of_node;               // node tag -> vertex
};

[[noreturn]] void fail_at(const std::string& path, long line, const std::string& message) {
  throw InputError(input_location(path, line, "mesh.file") + message);
}

[[noreturn]] void fail(const MshFile& file, const std::string& message) {
  fail_at(file.path, file.line, message);
}

// Reads the next non-blank line into file.text; false at the end of the file.
bool next_line(MshFile& file) {
  while (std::getline(file.in, file.text)) {
    ++file.line;
    file.text.erase(file.text.find_last_not_of(" \t\r") + 1);  // npos + 1 == 0 clears it
    if (!file.text.empty()) return true;
  }
  return false;
}

// The next line inside `section`, split into fields; the file must not end there.
std::istringstream section_line(MshFile& file, const std::string& section) {
  if (!next_line(file)) fail(file, "the file ends inside " + section);
  return std::istringstream(file.text);
}

template <class T>
T read_field(std::istringstream& fields, const MshFile& file, const std::string& what) {
  T value{};
  if (!(fields >> value)) fail(file, "expected " + what + " in \"" + file.text + "\"");
  return value;
}

long long read_count(std::istringstream& fields, const MshFile& file, const std::string& what) {
  const auto count = read_field<long long>(fields, file, what);
  if (count < 0) fail(file, what + " is negative in \"" + file.text + "\"");
  return count;
}

void expect_no_more_fields(std::istringstream& fields, const MshFile& file) {
  std::string extra;
  if (fields >> extra) fail(file, "unexpected \"" + extra + "\" in \"" + file.text + "\"");
}

// "$Nodes" -> "$EndNodes"
std::string end_of(const std::string& section) { return "$End" + section.substr(1); }

void expect_section_end(MshFile& file, const std::string& section) {
  section_line(file, section);
  if (file.text != end_of(section))
    fail(file, "expected " + end_of(section) + ", found \"" + file.text + "\"");
}

void skip_section(MshFile& file, const std::string& section) {
  do section_line(file, section);
  while (file.text != end_of(section));
}

void read_mesh_format(MshFile& file) {
  auto fields = section_line(file, "$MeshFormat");
  const auto version = read_field<std::string>(fields, file, "the format version");
  const auto file_type = read_field<int>(fields, file, "the file type");
  if (version != "4.1")
    fail(file, "Gmsh format " + version + " is not supported; save as MSH 4.1 (-format msh41)");
  if (file_type != 0) fail(file, "binary Gmsh files are not supported; save as ASCII");
  expect_section_end(file, "$MeshFormat");
}

// Lines `dim tag "name"`; the name may hold blanks.
void read_physical_names(MshFile& file, MshModel& model) {
  auto header = section_line(file, "$PhysicalNames");
  const auto count = read_count(header, file, "the number of physical names");
  for (long long i = 0; i < count; ++i) {
    auto fields = section_line(file, "$PhysicalNames");
    const auto dim = read_field<int>(fields, file, "a dimension");
    const auto tag = read_field<int>(fields, file, "a physical tag");
    const auto open = file.text.find('"'), close = file.text.rfind('"');
    if (open == std::string::npos || close == open) fail(file, "expected a quoted name");
    model.physical_names[{dim, tag}] = file.text.substr(open + 1, close - open - 1);
  }
  expect_section_end(file, "$PhysicalNames");
}

// One record per point, curve, surface, volume: tag, point or bounding box, physical tags,
// then bounding entities (not needed here).
void read_entities(MshFile& file, MshModel& model) {
  auto header = section_line(file, "$Entities");
  long long counts[4];
  for (auto& count : counts) count = read_count(header, file, "an entity count");
  for (int dim = 0; dim < 4; ++dim) {
    for (long long i = 0; i < counts[dim]; ++i) {
      auto fields = section_line(file, "$Entities");
      const auto tag = read_field<int>(fields, file, "an entity tag");
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) read_field<double>(fields, file, "a coordinate");
      std::vector<int> physicals;
      const auto physical_count = read_count(fields, file, "the number of physical tags");
      for (long long p = 0; p < physical_count; ++p)
        physicals.push_back(read_field<int>(fields, file, "a physical tag"));
      if (dim == 1) model.curve_physicals[tag] = physicals;
      if (dim == 2) model.surface_physicals[tag] = physicals;
    }
  }
  expect_section_end(file, "$Entities");
}

// Rejects a mesh whose largest |z| (on line `z_line`) is not small against its x-y extent.
void check_planar(const MshFile& file, const MeshInput& mesh, double max_abs_z, long z_line) {
  if (mesh.vx.empty()) return;
  const auto [x_min, x_max] = std::minmax_element(mesh.vx.begin(), mesh.vx.end());
  const auto [y_min, y_max] = std::minmax_element(mesh.vy.begin(), mesh.vy.end());
  const double size = std::max(*x_max - *x_min, *y_max - *y_min);
  if (max_abs_z > 1e-12 * size)
    fail_at(file.path, z_line, "mesh is not planar: nodes must lie in the plane z = 0");
}

// Blocks of node tags then coordinates "x y z", followed by entityDim parametric coordinates
// when the block's parametric flag is 1. Tags may be sparse: vertices are numbered in order.
void read_nodes(MshFile& file, MshModel& model, MeshInput& mesh) {
  auto header = section_line(file, "$Nodes");
  const auto blocks = read_count(header, file, "the number of node blocks");
  double max_abs_z = 0.0;
  long z_line = 0;
  for (long long b = 0; b < blocks; ++b) {
    auto fields = section_line(file, "$Nodes");
    const auto dim = read_field<int>(fields, file, "an entity dimension");
    read_field<int>(fields, file, "an entity tag");
    const auto parametric = read_field<int>(fields, file, "the parametric flag");
    const auto count = read_count(fields, file, "the number of nodes");
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
      fail(file, "bad node block header \"" + file.text + "\"");
    std::vector<long long> tags;
    for (long long i = 0; i < count; ++i) {
      auto tag_fields = section_line(file, "$Nodes");
      tags.push_back(read_field<long long>(tag_fields, file, "a node tag"));
      expect_no_more_fields(tag_fields, file);
    }
    for (const auto tag : tags) {
      auto coordinates = section_line(file, "$Nodes");
      const auto x = read_field<double>(coordinates, file, "x");
      const auto y = read_field<double>(coordinates, file, "y");
      const auto z = read_field<double>(coordinates, file, "z");
      for (int p = 0; p < parametric * dim; ++p)
        read_field<double>(coordinates, file, "a parametric coordinate");
      expect_no_more_fields(coordinates, file);
      if (!model.vertex_of_node.emplace(tag, static_cast<index_t>(mesh.vx.size())).second)
        fail(file, "node " + std::to_string(tag) + " is defined twice");
      mesh.vx.push_back(x);
      mesh.vy.push_back(y);
      if (std::abs(z) > max_abs_z) {
        max_abs_z = std::abs(z);
        z_line = file.line;
      }
    }
  }
  expect_section_end(file, "$Nodes");
  check_planar(file, mesh, max_abs_z, z_line);
}

std::string physical_name(const MshFile& file, const MshModel& model, int dim, int tag) {
  const auto found = model.physical_names.find({dim, tag});
  const std::string group = (dim == 1 ? "physical curve " : "physical surface ") +
                            std::to_string(tag);
  if (found == model.physical_names.end()) fail(file, group + " has no name in $PhysicalNames");
  return found->second;
}

// The material of the triangles of surface `entity`: the name of its one physical surface.
std::string surface_material(const MshFile& file, const MshModel& model, int entity) {
  const auto found = model.surface_physicals.find(entity);
  const std::string surface = "surface " + std::to_string(entity);
  if (found == model.surface_physicals.end()) fail(file, surface + " is not in $Entities");
  if (found->second.empty())
    fail(file, surface + " is in no physical surface, so its triangles have no material");
  if (found->second.size() > 1)
    fail(file, surface + " is in several physical surfaces; give it exactly one (its material)");
  return physical_name(file, model, 2, found->second.front());
}

// The boundary names of the lines of curve `entity`: one per physical curve, maybe none.
std::vector<std::string> curve_boundaries(const MshFile& file, const MshModel& model,
                                          int entity) {
  const auto found = model.curve_physicals.find(entity);
  if (found == model.curve_physicals.end())
    fail(file, "curve " + std::to_string(entity) + " is not in $Entities");
  std::vector<std::string> names;
  for (const int tag : found->second) names.push_back(physical_name(file, model, 1, tag));
  return names;
}

// Names of element types a 2D mesh may hold by mistake, for the error message.
std::string element_type_name(int type) {
  switch (type) {
    case 3: return " (4-node quadrangle)";
    case 4: return " (4-node tetrahedron)";
    case 8: return " (3-node line)";
    case 9: return " (6-node triangle)";
    case 16: return " (8-node quadrangle)";
    default: return "";
  }
}

// Number of nodes of the element types read; other types are rejected.
int nodes_per_element(const MshFile& file, int type, int entity_dim) {
  const int dim = type == 2 ? 2 : type == 1 ? 1 : 0;
  if (type != 1 && type != 2 && type != 15)
    fail(file, "element type " + std::to_string(type) + element_type_name(type) +
                   " is not supported; only 3-node triangles, 2-node lines and points");
  if (dim != entity_dim)
    fail(file, "element type " + std::to_string(type) + " on an entity of dimension " +
                   std::to_string(entity_dim));
  return type == 15 ? 1 : dim + 1;
}

// Blocks of elements of one type on one entity: a line per element, "tag node node ...".
void read_elements(MshFile& file, const MshModel& model, MeshInput& mesh) {
  auto header = section_line(file, "$Elements");
  const auto blocks = read_count(header, file, "the number of element blocks");
  for (long long b = 0; b < blocks; ++b) {
    auto fields = section_line(file, "$Elements");
    const auto dim = read_field<int>(fields, file, "an entity dimension");
    const auto entity = read_field<int>(fields, file, "an entity tag");
    const auto type = read_field<int>(fields, file, "an element type");
    const auto count = read_count(fields, file, "the number of elements");
    const int nodes = nodes_per_element(file, type, dim);
    const std::string material = type == 2 ? surface_material(file, model, entity) : "";
    const auto boundaries = type == 1 ? curve_boundaries(file, model, entity)
                                      : std::vector<std::string>{};
    for (long long e = 0; e < count; ++e) {
      auto element = section_line(file, "$Elements");
      read_field<long long>(element, file, "an element tag");
      std::vector<index_t> vertices;
      for (int n = 0; n < nodes; ++n) {
        const auto tag = read_field<long long>(element, file, "a node tag");
        const auto found = model.vertex_of_node.find(tag);
        if (found == model.vertex_of_node.end())
          fail(file, "node " + std::to_string(tag) + " is not in $Nodes");
        vertices.push_back(found->second);
      }
      expect_no_more_fields(element, file);
      if (type == 2) {
        mesh.tri.insert(mesh.tri.end(), vertices.begin(), vertices.end());
        mesh.tri_material.push_back(material);
      }
      for (const auto& name : boundaries) {
        auto& edges = mesh.boundaries[name];
        edges.insert(edges.end(), vertices.begin(), vertices.end());
      }
    }
  }
  expect_section_end(file, "$Elements");
}

}  // namespace

MeshInput read_gmsh(std::istream& in, const std::string& path) {
  MshFile file{path, in, 0, ""};
  MshModel model;
  MeshInput mesh;
  bool have_format = false;
  while (next_line(file)) {
    const std::string section = file.text;
    if (section.front() != '$') fail(file, "expected a section, found \"" + section + "\"");
    if (!have_format && section != "$MeshFormat") fail(file, "not a Gmsh mesh: no $MeshFormat");
    if (section == "$MeshFormat") {
      read_mesh_format(file);
      have_format = true;
    } else if (section == "$PhysicalNames") {
      read_physical_names(file, model);
    } else if (section == "$Entities") {
      read_entities(file, model);
    } else if (section == "$PartitionedEntities") {
      fail(file, "partitioned meshes are not supported");
    } else if (section == "$Nodes") {
      read_nodes(file, model, mesh);
    } else if (section == "$Elements") {
      read_elements(file, model, mesh);
    } else {
      skip_section(file, section);
    }
  }
  if (!have_format) fail_at(path, 0, "empty file, or not a Gmsh mesh");
  if (mesh.triangle_count() == 0) fail_at(path, 0, "no 3-node triangles in the mesh");
  return mesh;
}

MeshInput read_gmsh(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail_at(path, 0, "cannot open the mesh file");
  return read_gmsh(in, path);
}

}  // namespace ydry
