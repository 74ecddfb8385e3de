// SPDX-License-Identifier: MIT
// A model pressure matrix for the pressure solver's tests: the CFD-DEM's model-A operator on a box, with a void
// fraction that moves, so matrices of one pattern and changing coefficients can be made.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "unresolved/fvm/pressure_solver.hpp"

namespace hs::unresolved::pressure_model {

constexpr int kN = 20;   // cells per side: 8000 rows, a few ms per set-up

/// Appends one row, given as (column, value) pairs in any order, to a CSR matrix being built row by row.
inline void append_row(CsrMatrix& a, std::vector<std::pair<int, double>> row) {
  std::sort(row.begin(), row.end());
  for (const auto& [col, v] : row) {
    a.cols.push_back(col);
    a.values.push_back(v);
  }
  a.row_ptr.push_back(static_cast<int>(a.cols.size()));
}

/// The model-A pressure operator on a kN^3 box: face coefficients eps_f^2 (eps the mean of the two cells), a
/// fixed-pressure boundary half a cell away (2 eps^2 on the diagonal), so it is SPD like the solver's.
inline CsrMatrix pressure_matrix(const std::vector<double>& eps) {
  const auto id = [](int i, int j, int k) { return (k * kN + j) * kN + i; };
  CsrMatrix a;
  a.rows = kN * kN * kN;
  a.row_ptr.push_back(0);
  for (int k = 0; k < kN; ++k) {
    for (int j = 0; j < kN; ++j) {
      for (int i = 0; i < kN; ++i) {
        const int r = id(i, j, k);
        double diag = 0.0;
        std::vector<std::pair<int, double>> row;
        for (int ax = 0; ax < 3; ++ax) {
          for (const int s : {-1, 1}) {
            int n[3] = {i, j, k};
            n[ax] += s;
            if (n[ax] < 0 || n[ax] >= kN) {
              diag += 2.0 * eps[static_cast<std::size_t>(r)] * eps[static_cast<std::size_t>(r)];
              continue;
            }
            const int q = id(n[0], n[1], n[2]);
            const double e = 0.5 * (eps[static_cast<std::size_t>(r)] + eps[static_cast<std::size_t>(q)]);
            diag += e * e;
            row.emplace_back(q, -e * e);
          }
        }
        row.emplace_back(r, diag);
        append_row(a, std::move(row));
      }
    }
  }
  return a;
}

/// A void fraction with "cells" (eps down to 0.6) at positions shifted by `shift` cells along x.
inline std::vector<double> void_fraction(double shift) {
  std::vector<double> eps(static_cast<std::size_t>(kN * kN * kN), 1.0);
  for (int k = 0; k < kN; ++k) {
    for (int j = 0; j < kN; ++j) {
      for (int i = 0; i < kN; ++i) {
        const double x = i - shift;
        const double bump = std::sin(0.9 * x) * std::sin(0.7 * j) * std::sin(1.1 * k);
        eps[static_cast<std::size_t>((k * kN + j) * kN + i)] = 0.8 + 0.2 * bump;
      }
    }
  }
  return eps;
}

/// ||b - A x|| for a whole (one-rank) matrix.
inline double residual_norm(const CsrMatrix& a, const std::vector<double>& b, const std::vector<double>& x) {
  double r2 = 0.0;
  for (int r = 0; r < a.rows; ++r) {
    double ax = 0.0;
    for (int q = a.row_ptr[static_cast<std::size_t>(r)]; q < a.row_ptr[static_cast<std::size_t>(r) + 1]; ++q) {
      ax += a.values[static_cast<std::size_t>(q)] * x[static_cast<std::size_t>(a.cols[static_cast<std::size_t>(q)])];
    }
    r2 += (b[static_cast<std::size_t>(r)] - ax) * (b[static_cast<std::size_t>(r)] - ax);
  }
  return std::sqrt(r2);
}

inline double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (const double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace hs::unresolved::pressure_model
