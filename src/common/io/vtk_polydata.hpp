// SPDX-License-Identifier: MIT
// VTK XML PolyData (.vtp, appended raw binary) for membranes (triangles) and particles (vertices).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace hs::common {

class VtkPolyData {
 public:
  /// Points in metres. With no triangles the points are written as vertices (particles).
  explicit VtkPolyData(std::span<const Vec3> points_m, std::span<const std::array<int, 3>> triangles = {});

  void add_point_scalar(const std::string& name, std::span<const double> values);
  /// An integer label per point (an index, a category), written as VTK Int32.
  void add_point_scalar(const std::string& name, std::span<const std::int32_t> values);
  void add_point_vector(const std::string& name, std::span<const Vec3> values);
  void write(const std::filesystem::path& file) const;

 private:
  struct Array {
    std::string name;
    int components;
    std::vector<double> values;
    std::vector<std::int32_t> labels;   // used instead of values when `integer`
    bool integer = false;
  };
  std::vector<Vec3> points_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Array> arrays_;
};

/// A ParaView time series (.pvd) listing one file per output time; rewritten atomically on each add.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path file);
  /// `dataset` is relative to the .pvd's folder.
  void add(double time_s, const std::string& dataset);

 private:
  std::filesystem::path file_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace hs::common
