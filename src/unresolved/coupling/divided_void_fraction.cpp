// SPDX-License-Identifier: MIT
// The "divided" particle-to-grid map of CFDEM: marker positions, cell location, void fraction.
#include "unresolved/coupling/divided_void_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <omp.h>

#include "common/errors.hpp"
#include "unresolved/coupling/diffusion_smoothing.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

/// Volume-centroid radius of the shell between a and b (unit sphere): (3/4)(b^4 - a^4)/(b^3 - a^3).
double centroid_radius(double a, double b) {
  return 0.75 * (std::pow(b, 4) - std::pow(a, 4)) / (std::pow(b, 3) - std::pow(a, 3));
}

std::array<Vec3, kMarkersPerSphere> make_markers() {
  std::array<Vec3, kMarkersPerSphere> m{};
  const double r1 = std::cbrt(1.0 / 29.0);
  const double r2 = std::cbrt(15.0 / 29.0);
  const std::array<double, 2> radius{centroid_radius(r1, r2), centroid_radius(r2, 1.0)};
  const double s = std::sqrt(0.5);   // sin 45 deg = cos 45 deg
  std::size_t k = 1;   // m[0] is the centre
  for (const double r : radius) {
    for (const double cz : {s, -s}) {        // polar angle 45 and 135 deg
      for (const double az : {45.0, 135.0, 225.0, 315.0}) {
        const double phi = az * std::numbers::pi / 180.0;
        m[k++] = Vec3{r * s * std::cos(phi), r * s * std::sin(phi), r * cz};
      }
    }
    for (int a = 0; a < 3; ++a) {
      for (const double sign : {1.0, -1.0}) {
        Vec3 v{};
        v[a] = sign * r;
        m[k++] = v;
      }
    }
  }
  return m;
}

}  // namespace

const std::array<Vec3, kMarkersPerSphere>& divided_markers() {
  static const std::array<Vec3, kMarkersPerSphere> markers = make_markers();
  return markers;
}

DividedMap::DividedMap(const FvmGrid& grid) : grid_(grid), cell_volume_m3_(std::pow(grid.dx_m(), 3)) {}

void DividedMap::locate(const ParticleStore& particles) {
  const std::size_t n = particles.n_owned();
  cells_.assign(n * kMarkersPerSphere, 0);
  const auto& pos = particles.position_m();
  const auto& markers = divided_markers();
  const BlockField<double>& ff = grid_.fluid_fractions();
  bool lost = false;
#pragma omp parallel for schedule(static) reduction(|| : lost) if (n > 4096)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x{pos[0][i], pos[1][i], pos[2][i]};
    const auto centre = grid_.cell_of(x);
    if (!centre) {
      lost = true;   // thrown below: an exception must not leave an OpenMP region
      continue;
    }
    const std::size_t c0 = ff.index((*centre)[0], (*centre)[1], (*centre)[2]);
    for (int m = 0; m < kMarkersPerSphere; ++m) {
      const auto at = grid_.cell_of(x + particles.radius_m()[i] * markers[static_cast<std::size_t>(m)]);
      std::size_t c = c0;
      if (at && ff((*at)[0], (*at)[1], (*at)[2]) > 0.0) c = ff.index((*at)[0], (*at)[1], (*at)[2]);
      cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)] = c;
    }
  }
  if (lost) throw hs::common::NumericalError("coupling: a particle centre left the fluid grid");
  sort_by_cell(ff.data().size());
}

void DividedMap::sort_by_cell(std::size_t n_cells) {
  // Counting sort, stable in the marker index: each thread counts a contiguous range of markers; a cell's markers
  // from thread 0 come first, then thread 1's, ..., so the order is ascending k at any thread count.
  const std::size_t n_markers = cells_.size();
  const int n_threads = n_markers > 16 * static_cast<std::size_t>(kParallelCells) ? omp_get_max_threads() : 1;
  std::vector<std::vector<std::uint32_t>> count(static_cast<std::size_t>(n_threads));
  start_.assign(n_cells + 1, 0);
  markers_.resize(n_markers);
#pragma omp parallel num_threads(n_threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t lo = n_markers * t / count.size(), hi = n_markers * (t + 1) / count.size();
    std::vector<std::uint32_t>& mine = count[t];
    mine.assign(n_cells, 0);
    for (std::size_t k = lo; k < hi; ++k) ++mine[cells_[k]];
#pragma omp barrier
#pragma omp single
    {
      std::uint32_t total = 0;
      for (std::size_t c = 0; c < n_cells; ++c) {
        start_[c] = total;
        for (auto& per_thread : count) {   // becomes each thread's first slot in cell c
          const std::uint32_t n_here = per_thread[c];
          per_thread[c] = total;
          total += n_here;
        }
      }
      start_[n_cells] = total;
    }
    for (std::size_t k = lo; k < hi; ++k) markers_[mine[cells_[k]]++] = static_cast<std::uint32_t>(k);
  }
  occupied_.clear();
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (start_[c + 1] > start_[c]) occupied_.push_back(c);
  }
}

double DividedMap::void_fraction(const ParticleStore& particles, double eps_min, BlockField<double>& eps,
                                 DiffusionSmoothing* smoothing) const {
  BlockField<double> solid(grid_.cells(), 0.0);
  for_each_cell([&](std::size_t c, std::size_t k) {
    const double r = particles.radius_m()[k / kMarkersPerSphere];
    solid[c] += 4.0 / 3.0 * std::numbers::pi * r * r * r / kMarkersPerSphere;
  });
  // Every stored cell (ghosts too: the solver refills them before use); the clip below walks the interior.
  const std::vector<double>& ff = grid_.fluid_fractions().data();
  for (std::size_t c = 0; c < ff.size(); ++c) {
    if (ff[c] > 0.0) solid[c] /= fluid_volume_m3(c);
  }
  if (smoothing != nullptr) smoothing->smooth(solid);   // conserved: what the particles put on the grid stays there
  for (std::size_t c = 0; c < ff.size(); ++c) {
    if (ff[c] > 0.0) eps[c] = 1.0 - solid[c];
  }
  return clip_void_fraction(eps_min, eps);
}

double DividedMap::clip_void_fraction(double eps_min, BlockField<double>& eps) const {
  double lost_m3 = 0.0;
  const BlockField<double>& ff = grid_.fluid_fractions();
  const auto& n = grid_.cells();
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t c = ff.index(i, j, k);
        if (ff[c] <= 0.0) {
          eps[c] = 1.0;
          continue;
        }
        if (eps[c] < eps_min) lost_m3 += (eps_min - eps[c]) * fluid_volume_m3(c);
        eps[c] = std::max(eps[c], eps_min);
      }
    }
  }
  return lost_m3;
}

}  // namespace hs::unresolved
