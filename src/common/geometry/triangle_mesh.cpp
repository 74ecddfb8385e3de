// SPDX-License-Identifier: MIT
// Reading and checking closed triangle surfaces (STL).
#include "common/geometry/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::common {
namespace {

std::vector<Vec3> read_binary(const std::string& bytes, const std::string& name) {
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() < 84 + 50ull * n) throw ConfigError(fmt::format("{}: binary STL truncated ({} triangles declared)", name, n));
  std::vector<Vec3> corners;
  corners.reserve(3ull * n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + 84 + 50ull * t + 12;   // skip the stored normal: we recompute it
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 * v, 12);
      corners.push_back({xyz[0], xyz[1], xyz[2]});
    }
  }
  return corners;
}

std::vector<Vec3> read_ascii(const std::string& text) {
  std::vector<Vec3> corners;
  std::istringstream in(text);
  std::string word;
  while (in >> word) {
    if (word == "vertex") {
      Vec3 p;
      in >> p.x >> p.y >> p.z;
      corners.push_back(p);
    }
  }
  return corners;
}

}  // namespace

double TriangleMesh::signed_volume() const {
  double v = 0.0;
  for (const auto& t : triangles) v += dot(vertices[t[0]], cross(vertices[t[1]], vertices[t[2]]));
  return v / 6.0;
}

TriangleMesh read_stl(const std::filesystem::path& file, double scale_to_m) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(fmt::format("{}: cannot read STL file", name));
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 15) throw ConfigError(fmt::format("{}: not an STL file (too short)", name));
  // An ASCII file starts with "solid" and holds "facet"; some binary files also start with "solid", so
  // the size rule of binary STL decides when it fits.
  bool binary = true;
  if (bytes.compare(0, 5, "solid") == 0 && bytes.find("facet") != std::string::npos) {
    std::uint32_t n = 0;
    if (bytes.size() >= 84) std::memcpy(&n, bytes.data() + 80, 4);
    binary = bytes.size() >= 84 && bytes.size() == 84 + 50ull * n;
  }
  if (binary && bytes.size() < 84) throw ConfigError(fmt::format("{}: not an STL file", name));
  const std::vector<Vec3> corners = binary ? read_binary(bytes, name) : read_ascii(bytes);
  if (corners.empty() || corners.size() % 3 != 0) throw ConfigError(fmt::format("{}: STL holds no complete triangles", name));

  // Weld corners that coincide to within 1e-9 of the model size (STL repeats each vertex per triangle).
  Vec3 lo = corners.front();
  Vec3 hi = corners.front();
  for (const auto& c : corners) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], c[i]);
      hi[i] = std::max(hi[i], c[i]);
    }
  }
  const double quantum = std::max(norm(hi - lo), 1e-300) * 1e-9;
  std::map<std::tuple<long long, long long, long long>, int> index;
  TriangleMesh mesh;
  std::array<int, 3> tri{};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const auto key = std::make_tuple(std::llround(corners[i].x / quantum), std::llround(corners[i].y / quantum),
                                     std::llround(corners[i].z / quantum));
    auto [it, inserted] = index.emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(corners[i] * scale_to_m);
    tri[i % 3] = it->second;
    if (i % 3 == 2) mesh.triangles.push_back(tri);
  }
  return mesh;
}

void require_closed_manifold(TriangleMesh& mesh, const std::string& source) {
  std::map<std::pair<int, int>, int> directed;   // directed edge -> count
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        norm(cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]], mesh.vertices[tri[2]] - mesh.vertices[tri[0]])) == 0.0) {
      throw ConfigError(fmt::format("{}: triangle {} is degenerate (zero area); repair the surface", source, t));
    }
    for (int e = 0; e < 3; ++e) ++directed[{tri[e], tri[(e + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto opposite = directed.find({edge.second, edge.first});
    const int back = opposite == directed.end() ? 0 : opposite->second;
    const auto& a = mesh.vertices[edge.first];
    if (count + back == 1) {
      throw ConfigError(fmt::format("{}: open surface: the edge at ({:.4g}, {:.4g}, {:.4g}) m belongs to one triangle only; "
                                    "a closed (watertight) surface is required",
                                    source, a.x, a.y, a.z));
    }
    if (count + back > 2) {
      throw ConfigError(fmt::format("{}: non-manifold surface: the edge at ({:.4g}, {:.4g}, {:.4g}) m is shared by {} triangles",
                                    source, a.x, a.y, a.z, count + back));
    }
    if (count != 1 || back != 1) {
      throw ConfigError(fmt::format("{}: inconsistently oriented triangles at ({:.4g}, {:.4g}, {:.4g}) m; "
                                    "all normals must point the same way (outward)",
                                    source, a.x, a.y, a.z));
    }
  }
  if (mesh.signed_volume() < 0.0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);   // inward normals: the enclosed region is still clear
  }
}

}  // namespace hs::common
