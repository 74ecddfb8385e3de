// SPDX-License-Identifier: MIT
// VTK XML ImageData (.vti, appended raw binary) for lattice and grid fields, readable by ParaView.
#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace hs::common {

/// A field on the nodes of a uniform grid: nx*ny*nz points, x fastest. Coordinates in metres.
class VtkImage {
 public:
  VtkImage(std::array<int, 3> points, Vec3 origin_m, double spacing_m);

  /// Scalar per point (size nx*ny*nz). Stored as Float32 unless `float64`.
  void add_scalar(const std::string& name, std::span<const double> values, bool float64 = false);
  /// Vector per point, interleaved xyz (size 3*nx*ny*nz).
  void add_vector(const std::string& name, std::span<const double> xyz, bool float64 = false);
  /// Writes the file atomically.
  void write(const std::filesystem::path& file) const;

 private:
  struct Array {
    std::string name;
    int components;
    bool float64;
    std::vector<char> bytes;
  };
  void add(const std::string& name, std::span<const double> values, int components, bool float64);

  std::array<int, 3> points_;
  Vec3 origin_m_;
  double spacing_m_;
  std::vector<Array> arrays_;
};

/// Reads one named point array of a .vti written by VtkImage (for tests and restarts), as doubles.
std::vector<double> read_vti_array(const std::filesystem::path& file, const std::string& name);

}  // namespace hs::common
