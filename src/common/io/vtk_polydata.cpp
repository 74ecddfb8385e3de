// SPDX-License-Identifier: MIT
// VTK XML PolyData (.vtp) and ParaView .pvd series.
#include "common/io/vtk_polydata.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <stdexcept>

#include <fmt/format.h>

#include "common/io/atomic_file.hpp"

namespace hs::common {
namespace {

template <typename T>
void append_block(std::vector<char>& blob, const std::vector<T>& data) {
  const std::uint64_t nbytes = data.size() * sizeof(T);
  const std::size_t at = blob.size();
  blob.resize(at + sizeof nbytes + nbytes);
  std::memcpy(blob.data() + at, &nbytes, sizeof nbytes);
  if (nbytes > 0) std::memcpy(blob.data() + at + sizeof nbytes, data.data(), nbytes);
}

}  // namespace

VtkPolyData::VtkPolyData(std::span<const Vec3> points_m, std::span<const std::array<int, 3>> triangles)
    : points_(points_m.begin(), points_m.end()), triangles_(triangles.begin(), triangles.end()) {}

void VtkPolyData::add_point_scalar(const std::string& name, std::span<const double> values) {
  if (values.size() != points_.size()) throw std::logic_error("VtkPolyData: scalar size mismatch for " + name);
  arrays_.push_back(
      {.name = name, .components = 1, .values = {values.begin(), values.end()}, .labels = {}, .integer = false});
}

void VtkPolyData::add_point_scalar(const std::string& name, std::span<const std::int32_t> values) {
  if (values.size() != points_.size()) throw std::logic_error("VtkPolyData: scalar size mismatch for " + name);
  arrays_.push_back(
      {.name = name, .components = 1, .values = {}, .labels = {values.begin(), values.end()}, .integer = true});
}

void VtkPolyData::add_point_vector(const std::string& name, std::span<const Vec3> values) {
  if (values.size() != points_.size()) throw std::logic_error("VtkPolyData: vector size mismatch for " + name);
  std::vector<double> flat;
  flat.reserve(3 * values.size());
  for (const auto& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
  arrays_.push_back({.name = name, .components = 3, .values = std::move(flat), .labels = {}, .integer = false});
}

void VtkPolyData::write(const std::filesystem::path& file) const {
  const bool as_vertices = triangles_.empty();
  std::vector<double> xyz;
  xyz.reserve(3 * points_.size());
  for (const auto& p : points_) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  if (as_vertices) {
    for (std::size_t i = 0; i < points_.size(); ++i) {
      connectivity.push_back(static_cast<std::int64_t>(i));
      offsets.push_back(static_cast<std::int64_t>(i + 1));
    }
  } else {
    for (const auto& t : triangles_) {
      connectivity.insert(connectivity.end(), {t[0], t[1], t[2]});
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  }
  // Appended layout: point-data arrays, points, connectivity, offsets; each block is a UInt64 size + data.
  std::vector<char> blob;
  auto declare = [&blob](const std::string& type, const std::string& name, int comps, const auto& data) {
    const std::string tag = fmt::format(
        "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" offset=\"{}\"/>\n", type,
        name, comps, blob.size());
    append_block(blob, data);
    return tag;
  };
  std::string point_data;
  for (const auto& a : arrays_) {
    point_data += a.integer ? declare("Int32", a.name, 1, a.labels)
                            : declare("Float64", a.name, a.components, a.values);
  }
  const std::string points_decl = declare("Float64", "Points", 3, xyz);
  const std::string cells_decl = declare("Int64", "connectivity", 1, connectivity) + declare("Int64", "offsets", 1, offsets);
  const std::string cells_tag = as_vertices ? "Verts" : "Polys";

  write_file_atomic(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PolyData>\n"
        << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfPolys=\"{}\">\n", points_.size(),
                       as_vertices ? points_.size() : 0, as_vertices ? 0 : triangles_.size())
        << "      <PointData>\n" << point_data << "      </PointData>\n"
        << "      <Points>\n" << points_decl << "      </Points>\n"
        << "      <" << cells_tag << ">\n" << cells_decl << "      </" << cells_tag << ">\n"
        << "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
    out.write(blob.data(), static_cast<std::streamsize>(blob.size()));
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

PvdSeries::PvdSeries(std::filesystem::path file) : file_(std::move(file)) {
  // A resumed run continues the series it already had.
  std::ifstream in(file_);
  const std::regex entry(R"(timestep=\"([^\"]+)\".*file=\"([^\"]+)\")");
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, entry)) entries_.emplace_back(std::stod(m[1].str()), m[2].str());
  }
}

void PvdSeries::add(double time_s, const std::string& dataset) {
  while (!entries_.empty() && entries_.back().first >= time_s) entries_.pop_back();   // after a resume
  entries_.emplace_back(time_s, dataset);
  std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection>\n";
  for (const auto& [t, f] : entries_) text += fmt::format("    <DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}\"/>\n", t, f);
  text += "  </Collection>\n</VTKFile>\n";
  write_file_atomic(file_, text);
}

}  // namespace hs::common
