// SPDX-License-Identifier: MIT
// Wavefront .obj reading/writing and .vtp writing of triangle meshes.
#include "resolved/membrane/mesh_io.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"
#include "common/io/vtk_polydata.hpp"

namespace hs::resolved {
namespace {

using hs::common::ConfigError;

int obj_index(const std::string& token, int vertex_count, const std::filesystem::path& file, int line_no) {
  const std::string head = token.substr(0, token.find('/'));
  int idx = 0;
  try {
    idx = std::stoi(head);
  } catch (const std::exception&) {
    throw ConfigError(fmt::format("{}:{}: face index '{}' is not an integer", file.string(), line_no, token));
  }
  const int zero_based = idx > 0 ? idx - 1 : vertex_count + idx;
  if (idx == 0 || zero_based < 0 || zero_based >= vertex_count) {
    throw ConfigError(fmt::format("{}:{}: face index {} is out of range (1..{} or negative relative indices)",
                                  file.string(), line_no, idx, vertex_count));
  }
  return zero_based;
}

}  // namespace

void write_mesh_obj(const TriangleMesh& mesh, const std::filesystem::path& file) {
  std::string text = fmt::format("# hemoscale RBC membrane mesh: {} vertices, {} triangles, coordinates in metres\n",
                                 mesh.vertex_count(), mesh.triangle_count());
  for (const auto& v : mesh.vertices_m) text += fmt::format("v {:.17g} {:.17g} {:.17g}\n", v.x, v.y, v.z);
  for (const auto& t : mesh.triangles) text += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  hs::common::write_file_atomic(file, text);
}

TriangleMesh read_mesh_obj(const std::filesystem::path& file, double length_unit_m) {
  std::ifstream in(file);
  if (!in) throw ConfigError(fmt::format("{}: cannot open the mesh file", file.string()));
  TriangleMesh mesh;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if (tag == "v") {
      hs::common::Vec3 p;
      if (!(ss >> p.x >> p.y >> p.z)) {
        throw ConfigError(fmt::format("{}:{}: vertex needs three numbers: '{}'", file.string(), line_no, line));
      }
      mesh.vertices_m.push_back(p * length_unit_m);
    } else if (tag == "f") {
      std::vector<int> corners;
      std::string token;
      while (ss >> token) corners.push_back(obj_index(token, mesh.vertex_count(), file, line_no));
      if (corners.size() < 3) {
        throw ConfigError(fmt::format("{}:{}: face needs at least 3 corners: '{}'", file.string(), line_no, line));
      }
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
  }
  if (mesh.vertices_m.empty() || mesh.triangles.empty()) {
    throw ConfigError(fmt::format("{}: no vertices or no faces found (expected 'v x y z' and 'f i j k' lines)", file.string()));
  }
  return mesh;
}

void write_mesh_vtp(const TriangleMesh& mesh, const std::filesystem::path& file) {
  hs::common::VtkPolyData vtp(mesh.vertices_m, mesh.triangles);
  vtp.add_point_vector("normal", vertex_normals(mesh));
  vtp.add_point_scalar("vertex_area_m2", vertex_areas_m2(mesh));
  vtp.write(file);
}

}  // namespace hs::resolved
