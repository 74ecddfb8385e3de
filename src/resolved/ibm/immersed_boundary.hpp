// SPDX-License-Identifier: MIT
// Immersed boundary coupling on the lattice: interpolation to markers, spreading of marker forces, multi-direct forcing.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "resolved/ibm/delta_kernel.hpp"
#include "resolved/lbm/fluid_lattice.hpp"

namespace hs::resolved {

struct IbmSettings {
  DeltaKernel kernel = DeltaKernel::four_point;   // Palabos-npFEM uses Peskin's phi4 (resolved-methods.md 2.1)
  int iterations = 1;                             // inamuro_iT = 1 in every shipped Palabos-npFEM case (2.2)
  bool measure_slip = false;                      // interpolate once more after the last iteration (diagnostics)
};

/// Lagrangian markers in lattice units: global lattice coordinates (may lie outside the periodic box: node
/// indices are wrapped, the markers are not), prescribed velocities, and Lagrangian weights (vertex areas, lu^2).
struct Markers {
  std::vector<common::Vec3> x_lu;
  std::vector<common::Vec3> u_lu;
  std::vector<double> area_lu;
};

/// Interpolated fluid state at the markers.
struct MarkerFluid {
  std::vector<double> rho_lu;
  std::vector<common::Vec3> u_lu;   // half-force velocity (includes the force field as it is now)
};

/// What one multi-direct forcing pass did (lattice units).
struct ForcingReport {
  double slip_before_lu = 0.0;          // max |U_k - u_k| before the first iteration
  double slip_after_lu = 0.0;           // max |U_k - u_k| after the last iteration (only with measure_slip)
  common::Vec3 total_force_lu;          // sum of the marker forces spread (= force on the fluid per step)
  /// Per marker: the force it spread onto the fluid this step, summed over the iterations (0 for a marker without
  /// any fluid node in reach, whose correction goes nowhere). Sums to total_force_lu up to those markers; minus it is
  /// the reaction on the membrane (CouplingSettings::membrane_force).
  std::vector<common::Vec3> marker_force_lu;
};

/// Immersed boundary operations on one FluidLattice. Every marker is known on every rank; each rank touches only
/// its own interior nodes and the per-marker sums are combined with MPI_Allreduce, so results do not depend on
/// the decomposition beyond round-off. Near a wall a stencil is cut: nodes outside the fluid (or beyond a
/// non-periodic face) get no force and do not enter the average, and the fluid nodes' weights are renormalised to sum to one. So spreading conserves the
/// total force there too (a cut stencil lost the wall nodes' share: momentum leaked into the walls, and the forcing
/// iterations over-drove the fluid), and interpolation stays the transpose of spreading. Stencils without a wall node
/// are untouched, bit for bit. Non-periodic axes: nodes beyond the box are skipped.
class ImmersedBoundary {
 public:
  ImmersedBoundary(FluidLattice& lattice, const IbmSettings& settings);

  /// rho and half-force u at each marker. Collective.
  [[nodiscard]] MarkerFluid interpolate(std::span<const common::Vec3> x_lu) const;
  /// Adds the point forces f_lu (lattice units, momentum per step) at the markers to the force field.
  void spread(std::span<const common::Vec3> x_lu, std::span<const common::Vec3> f_lu);
  /// After the force field was written elsewhere (a checkpoint restored): the next apply() clears all of it.
  void forget_forced_nodes() { forced_nodes_known_ = false; }
  /// Multi-direct forcing (Wang, Fan & Luo 2008; resolved-methods.md 2.2 with Guo forcing): clears the force
  /// field, then `iterations` times dF_k = 2 A_k (rho_k U_k - J_k), spread, so the half-force velocity
  /// u = (sum f c + F/2)/rho moves towards U_k at the markers. Collective.
  ForcingReport apply(const Markers& markers);

  /// Calls visit(local x, y, z, weight) for every interior node of this rank in the marker's stencil.
  void for_each_local_node(const common::Vec3& x_lu, const std::function<void(int, int, int, double)>& visit) const;
  /// Local interior coordinates of a global node (wrapped on periodic axes), or false if not on this rank.
  [[nodiscard]] bool to_local(std::array<int, 3> global, std::array<int, 3>& local) const;
  [[nodiscard]] const IbmSettings& settings() const { return settings_; }

 private:
  /// Per marker: 1 if its stencil is whole, else 1 / (sum of its fluid nodes' weights), 0 if it has none.
  /// Collective (a stencil may straddle ranks).
  [[nodiscard]] std::vector<double> cut_stencil_scale(std::span<const common::Vec3> x_lu) const;

  FluidLattice& lattice_;
  IbmSettings settings_;
  // apply(): per lattice node, its index among the nodes the stencils touch this step (-1: none). Neighbouring
  // markers' stencils overlap, so each node's moments are read once; reset after use, sized on first use.
  std::vector<std::int32_t> node_slot_;
  // The nodes apply() gave a force last time: the next apply() zeroes only them, not the whole field (3 doubles a
  // node, a memset of the lattice every step). False until then, and after spread(): then the whole field is cleared.
  std::vector<std::size_t> forced_nodes_;
  bool forced_nodes_known_ = false;
};

}  // namespace hs::resolved
