// SPDX-License-Identifier: MIT
// The cytoplasm's viscosity of the single-RBC cases: [cell] cytoplasm_viscosity_Pa_s and its checks.
#include "resolved/cases/cytoplasm_viscosity.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace hs::resolved {
namespace {

/// Smallest relaxation time allowed in either phase: the Bouzidi closure's correction grows as 1 / (tau - 1/2) and was
/// tested down to tau 0.6 (boundary_links.hpp); 0.55 leaves the lattice a margin below that, no more.
constexpr double kMinTau = 0.55;

}  // namespace

double read_cytoplasm_viscosity_ratio(hs::common::ConfigSection cell, double plasma_viscosity_Pa_s) {
  // Absent: a healthy cell's haemoglobin solution, 6 mPa s (Cokelet & Meiselman 1968, Science 162:275, as cited in
  // kHealthyCytoplasmViscosity_Pa_s), ratio 5.85 against the shipped plasma's 1.025 mPa s. A case that needs the
  // one-fluid cell of the runs before #27 gives the plasma's own viscosity (ratio 1 exactly).
  const double mu_in = cell.number_in_or("cytoplasm_viscosity_Pa_s", 1.0e-5, 1.0, kHealthyCytoplasmViscosity_Pa_s);
  double ratio = mu_in / plasma_viscosity_Pa_s;
  if (std::abs(ratio - 1.0) < 1e-12) ratio = 1.0;
  cell.derived("viscosity_ratio", ratio);
  return ratio;
}

void check_cytoplasm_relaxation(hs::common::ConfigSection cell, const CellNumerics& n) {
  if (n.viscosity_ratio == 1.0) return;
  const double tau_in = n.inner_collision.tau;
  const double tau_min = std::min(n.collision.tau, tau_in);
  if (tau_min < kMinTau) {
    cell.fail("cytoplasm_viscosity_Pa_s",
              fmt::format("gives the viscosity ratio {:.4g}, and with it tau = {:.4g} outside and {:.4g} in the cytoplasm; "
                          "both must be >= {:g}: raise [numerics] max_tau or lattice_velocity (ratio > 1), or the "
                          "lattice_velocity (ratio < 1); healthy cells: {:g} Pa s",
                          n.viscosity_ratio, n.collision.tau, tau_in, kMinTau, kHealthyCytoplasmViscosity_Pa_s));
  }
}

}  // namespace hs::resolved
