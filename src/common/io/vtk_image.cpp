// SPDX-License-Identifier: MIT
// VTK XML ImageData (.vti, appended raw binary).
#include "common/io/vtk_image.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/io/atomic_file.hpp"

namespace hs::common {

VtkImage::VtkImage(std::array<int, 3> points, Vec3 origin_m, double spacing_m)
    : points_(points), origin_m_(origin_m), spacing_m_(spacing_m) {}

void VtkImage::add(const std::string& name, std::span<const double> values, int components, bool float64) {
  const std::size_t n = static_cast<std::size_t>(points_[0]) * points_[1] * points_[2] * components;
  if (values.size() != n) throw std::logic_error(fmt::format("VtkImage: array {} has {} values, expected {}", name, values.size(), n));
  Array a{name, components, float64, {}};
  const std::uint64_t nbytes = n * (float64 ? 8 : 4);
  a.bytes.resize(sizeof nbytes + nbytes);
  std::memcpy(a.bytes.data(), &nbytes, sizeof nbytes);
  char* dst = a.bytes.data() + sizeof nbytes;
  for (std::size_t i = 0; i < n; ++i) {
    if (float64) {
      std::memcpy(dst + 8 * i, &values[i], 8);
    } else {
      const auto f = static_cast<float>(values[i]);
      std::memcpy(dst + 4 * i, &f, 4);
    }
  }
  arrays_.push_back(std::move(a));
}

void VtkImage::add_scalar(const std::string& name, std::span<const double> values, bool float64) {
  add(name, values, 1, float64);
}

void VtkImage::add_vector(const std::string& name, std::span<const double> xyz, bool float64) {
  add(name, xyz, 3, float64);
}

void VtkImage::write(const std::filesystem::path& file) const {
  write_file_atomic(file, [this](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << fmt::format("  <ImageData WholeExtent=\"0 {} 0 {} 0 {}\" Origin=\"{:.9g} {:.9g} {:.9g}\" Spacing=\"{:.9g} {:.9g} {:.9g}\">\n",
                       points_[0] - 1, points_[1] - 1, points_[2] - 1, origin_m_.x, origin_m_.y, origin_m_.z, spacing_m_,
                       spacing_m_, spacing_m_)
        << fmt::format("    <Piece Extent=\"0 {} 0 {} 0 {}\">\n", points_[0] - 1, points_[1] - 1, points_[2] - 1)
        << "      <PointData>\n";
    std::uint64_t offset = 0;
    for (const auto& a : arrays_) {
      out << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" offset=\"{}\"/>\n",
                         a.float64 ? "Float64" : "Float32", a.name, a.components, offset);
      offset += a.bytes.size();
    }
    out << "      </PointData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";
    for (const auto& a : arrays_) out.write(a.bytes.data(), static_cast<std::streamsize>(a.bytes.size()));
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

std::vector<double> read_vti_array(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto tag = content.find(fmt::format("Name=\"{}\"", name));
  const auto data = content.find("encoding=\"raw\">");
  if (tag == std::string::npos || data == std::string::npos) throw std::runtime_error("no array " + name + " in " + file.string());
  const auto line_start = content.rfind('<', tag);
  const std::string line = content.substr(line_start, content.find('>', tag) - line_start);
  const bool f64 = line.find("Float64") != std::string::npos;
  const auto off_pos = line.find("offset=\"") + 8;
  const std::uint64_t offset = std::stoull(line.substr(off_pos));
  const std::size_t base = content.find('_', data) + 1 + offset;
  std::uint64_t nbytes = 0;
  std::memcpy(&nbytes, content.data() + base, 8);
  const std::size_t n = nbytes / (f64 ? 8 : 4);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (f64) {
      std::memcpy(&out[i], content.data() + base + 8 + 8 * i, 8);
    } else {
      float f = 0.0f;
      std::memcpy(&f, content.data() + base + 8 + 4 * i, 4);
      out[i] = f;
    }
  }
  return out;
}

}  // namespace hs::common
