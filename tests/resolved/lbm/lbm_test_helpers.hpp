// SPDX-License-Identifier: MIT
// Shared set-ups of the lattice Boltzmann verification tests: channels, tubes, steady-state iteration.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "common/geometry/tube.hpp"
#include "resolved/lbm/fluid_lattice.hpp"

namespace hs::resolved::test {

/// Runs `lattice` in blocks of `block` steps until the largest change of any velocity component over one block,
/// relative to the largest speed, is below `tolerance` (an honest steady-state criterion), or `max_steps`.
/// Returns the number of steps run.
inline long run_to_steady_state(FluidLattice& lattice, double tolerance, long block, long max_steps) {
  std::vector<double> rho, u_old, u_new;
  lattice.macroscopic(rho, u_old);
  long steps = 0;
  while (steps < max_steps) {
    lattice.run(block);
    steps += block;
    lattice.macroscopic(rho, u_new);
    double change = 0.0;
    double speed = 1e-300;
    for (std::size_t k = 0; k < u_new.size(); ++k) {
      change = std::max(change, std::abs(u_new[k] - u_old[k]));
      speed = std::max(speed, std::abs(u_new[k]));
    }
    if (change < tolerance * speed) return steps;
    std::swap(u_old, u_new);
  }
  return steps;
}

/// A channel periodic in x and z with half-way bounce-back walls on the y faces: the walls sit at
/// y = -1/2 and y = ny - 1/2, so the channel width is H = ny.
inline std::unique_ptr<FluidLattice> make_channel(int ny, const CollisionParams& collision, MPI_Comm comm,
                                                  std::array<int, 3> ranks = {}) {
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {2, ny, 2}, .periodic = {true, false, true}, .collision = collision,
                  .ranks_per_axis = ranks, .rho0_lu = 1.0},
      comm);
  return lattice;
}

/// A periodic tube along z of radius `radius_lu`, axis at the centre of an (2R + 4)^2 cross-section.
struct TubeSetup {
  std::unique_ptr<common::Tube> shape;
  std::unique_ptr<FluidLattice> lattice;
  double centre_lu;
};

inline TubeSetup make_tube(double radius_lu, int nz, const CollisionParams& collision, WallRule rule, MPI_Comm comm,
                           std::array<int, 3> ranks = {}) {
  const int n = static_cast<int>(std::ceil(2.0 * radius_lu)) + 4;
  const double c = 0.5 * (n - 1);
  TubeSetup s;
  s.centre_lu = c;
  s.shape = std::make_unique<common::Tube>(
      common::TubeSpec{.start_m = {c, c, -1.0}, .end_m = {c, c, nz + 1.0}, .radius_m = radius_lu});
  s.lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {n, n, nz}, .periodic = {false, false, true}, .collision = collision,
                  .ranks_per_axis = ranks, .rho0_lu = 1.0},
      comm);
  s.lattice->set_shape(*s.shape, ShapePlacement{.origin = {}, .spacing = 1.0}, rule);
  return s;
}

}  // namespace hs::resolved::test
