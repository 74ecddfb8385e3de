// SPDX-License-Identifier: MIT
#include "unresolved/coupling/diffusion_smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::unresolved {

namespace {
constexpr double kRelativeTolerance = 1e-13;
constexpr int kMaxIterations = 1000;
}  // namespace

DiffusionSmoothing::DiffusionSmoothing(const FvmGrid& grid, double length_m) : length_m_(length_m) {
  if (!(length_m > 0.0) || !std::isfinite(length_m)) {
    throw hs::common::ConfigError(fmt::format("coupling: smoothing length {} m must be > 0", length_m));
  }
  const auto& n = grid.cells();
  const auto& fraction = grid.fluid_fractions();
  const double dx = grid.dx_m();
  // Compact rows: the interior cells with fluid, in flat-index order.
  std::vector<long> row_of(fraction.data().size(), -1);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t c = fraction.index(i, j, k);
        if (fraction[c] <= 0.0) continue;
        row_of[c] = static_cast<long>(cell_index_.size());
        cell_index_.push_back(c);
        volume_.push_back(fraction[c] * dx * dx * dx);
      }
    }
  }
  const double scale = length_m * length_m * dx;
  row_start_.push_back(0);
  for (std::size_t r = 0; r < cell_index_.size(); ++r) {
    // Recover (i, j, k) of the row's cell from its flat index.
    const std::size_t c = cell_index_[r];
    const long sy = fraction.stride(1);
    const long sz = fraction.stride(2);
    const std::array<int, 3> ijk{static_cast<int>(static_cast<long>(c) % sy) - 1,
                                 static_cast<int>((static_cast<long>(c) % sz) / sy) - 1,
                                 static_cast<int>(static_cast<long>(c) / sz) - 1};
    double diagonal = volume_[r];
    for (int a = 0; a < 3; ++a) {
      const int na = n[static_cast<std::size_t>(a)];
      for (const int side : {-1, 1}) {
        std::array<int, 3> nb = ijk;
        nb[static_cast<std::size_t>(a)] += side;
        if (nb[static_cast<std::size_t>(a)] < 0 || nb[static_cast<std::size_t>(a)] >= na) {
          if (!grid.periodic(a)) continue;   // the box's own faces: walls and openings let nothing diffuse out
          nb[static_cast<std::size_t>(a)] = (nb[static_cast<std::size_t>(a)] + na) % na;
        }
        if (na == 1) continue;   // a one-cell periodic axis: the cell is its own neighbour
        // The face between the two cells is the velocity node of the higher cell index (node 0 across a periodic wrap).
        const std::array<int, 3> face = side > 0 ? nb : ijk;
        const double area = grid.open_areas(a)(face[0], face[1], face[2]);
        const long other = row_of[fraction.index(nb[0], nb[1], nb[2])];
        if (area <= 0.0 || other < 0) continue;
        neighbour_.push_back(static_cast<std::size_t>(other));
        coefficient_.push_back(scale * area);
        diagonal += scale * area;
      }
    }
    diagonal_.push_back(diagonal);
    row_start_.push_back(neighbour_.size());
  }
  const std::size_t rows = cell_index_.size();
  r_.resize(rows);
  z_.resize(rows);
  p_.resize(rows);
  ap_.resize(rows);
}

void DiffusionSmoothing::apply(const std::vector<double>& x, std::vector<double>& y) const {
  for (std::size_t r = 0; r < x.size(); ++r) {
    double s = diagonal_[r] * x[r];
    for (std::size_t e = row_start_[r]; e < row_start_[r + 1]; ++e) s -= coefficient_[e] * x[neighbour_[e]];
    y[r] = s;
  }
}

int DiffusionSmoothing::solve(std::vector<double>& q) {
  // b = V q; the start x = q is exact where q is flat, so smooth regions converge at once.
  const std::size_t rows = q.size();
  std::vector<double>& x = q;
  double b_norm = 0.0;
  apply(x, ap_);
  double rz = 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    const double b = volume_[r] * q[r];
    b_norm += b * b;
    r_[r] = b - ap_[r];
    z_[r] = r_[r] / diagonal_[r];
    p_[r] = z_[r];
    rz += r_[r] * z_[r];
  }
  b_norm = std::sqrt(b_norm);
  if (b_norm == 0.0) return 0;
  for (int it = 0; it < kMaxIterations; ++it) {
    double r_norm = 0.0;
    for (std::size_t r = 0; r < rows; ++r) r_norm += r_[r] * r_[r];
    if (std::sqrt(r_norm) <= kRelativeTolerance * b_norm) return it;
    apply(p_, ap_);
    double pap = 0.0;
    for (std::size_t r = 0; r < rows; ++r) pap += p_[r] * ap_[r];
    const double alpha = rz / pap;
    double rz_new = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      x[r] += alpha * p_[r];
      r_[r] -= alpha * ap_[r];
      z_[r] = r_[r] / diagonal_[r];
      rz_new += r_[r] * z_[r];
    }
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t r = 0; r < rows; ++r) p_[r] = z_[r] + beta * p_[r];
  }
  throw hs::common::NumericalError(fmt::format(
      "coupling: the smoothing solve did not reach a relative residual of {:.0e} in {} iterations (smoothing length "
      "{:.4g} m)", kRelativeTolerance, kMaxIterations, length_m_));
}

void DiffusionSmoothing::smooth(BlockField<double>& q) {
  std::vector<double> x(cell_index_.size());
  for (std::size_t r = 0; r < x.size(); ++r) x[r] = q[cell_index_[r]];
  last_iterations_ = solve(x);
  for (std::size_t r = 0; r < x.size(); ++r) q[cell_index_[r]] = x[r];
}

void DiffusionSmoothing::smooth(BlockField<hs::common::Vec3>& q) {
  std::vector<double> x(cell_index_.size());
  int most = 0;
  for (int a = 0; a < 3; ++a) {
    for (std::size_t r = 0; r < x.size(); ++r) x[r] = q[cell_index_[r]][a];
    most = std::max(most, solve(x));
    for (std::size_t r = 0; r < x.size(); ++r) q[cell_index_[r]][a] = x[r];
  }
  last_iterations_ = most;
}

}  // namespace hs::unresolved
