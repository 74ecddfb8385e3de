// SPDX-License-Identifier: MIT
// The plasma flow of the periodic stenosed channel: the lattice that holds it, the lubrication estimate of the body
// force that drives a given flow rate, the flow rate measured plane by plane, and the drive calibrated on plasma alone.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "common/units/unit_converter.hpp"
#include "resolved/cases/stenosis_cell_config.hpp"
#include "resolved/lbm/fluid_lattice.hpp"

namespace hs::resolved {

/// Lattice nodes and the SI position of node (0, 0, 0): node i sits at x = i dx, node j at y = (j - 5/2) dx, so the
/// straight walls y = 0 and y = H fall half-way between nodes (Bouzidi reduces to half-way bounce-back there) with two
/// solid nodes beyond each; z is periodic.
struct StenosisGrid {
  std::array<int, 3> nodes{};
  common::Vec3 origin_m;
};
[[nodiscard]] StenosisGrid stenosis_grid(const StenosisCellConfig& c);

/// The channel lattice (periodic x and z, walls of StenosedChannel by c.numerics.wall), force field enabled, at rest.
/// Collective over MPI_COMM_WORLD.
[[nodiscard]] std::unique_ptr<FluidLattice> make_stenosis_lattice(const StenosisCellConfig& c, const StenosisGrid& grid);

/// Lubrication (locally plane-Poiseuille) body force per unit mass that drives the flow rate per width q through the
/// periodic channel: the local pressure-plus-body-force gradient is 12 mu q / h(x)^3 and the pressure returns to its
/// value over one period, so g = (12 nu q / L) int_0^L dx / h(x)^3 (midpoint rule, 20000 points).
[[nodiscard]] double lubrication_drive_m_s2(const StenosisCellConfig& c, double flow_rate_m2_s);

/// Volume flow rate per unit width through every global x-plane, q_i = sum_{y,z} rho u_x dx^2 / (rho0 W), SI (m^2/s),
/// summed over all ranks (collective). At steady state continuity makes it the same for every plane.
[[nodiscard]] std::vector<double> plane_flow_rates_m2_s(const FluidLattice& lattice, const common::UnitConverter& units,
                                                        double width_m);

/// Mass crossing each face between the x-planes of nodes i and i + 1 (periodic) in one step, in lattice units: the
/// populations that streamed from a fluid node on one side to a fluid node on the other, forward minus backward. Unlike
/// the nodal sums above (whose quadrature error near walls cut between nodes is O((dx / h)^2)), this is the lattice's
/// own mass flux: at steady state it is the same through every face up to the walls' mass balance. One rank only
/// (the tests): throws std::logic_error on more.
[[nodiscard]] std::vector<double> face_mass_fluxes_lu(const FluidLattice& lattice);

/// Mean of plane_flow_rates_m2_s over the planes: the flow rate per width of the whole box (collective).
[[nodiscard]] double mean_flow_rate_m2_s(const FluidLattice& lattice, const common::UnitConverter& units, double width_m);

/// Result of driving the plasma alone with a uniform body force until the flow rate is steady.
struct PlasmaFlow {
  double drive_m_s2 = 0.0;           // the body force applied
  std::vector<double> plane_flow_rates_m2_s;
  double mean_flow_rate_m2_s = 0.0;
  std::vector<double> face_mass_fluxes_lu;   // face_mass_fluxes_lu() on one rank; empty on more
  long steps = 0;
};

/// Runs the plasma alone (no cell) under `drive_m_s2` until the mean flow rate changes by less than `tolerance`
/// (relative) over H^2 / nu, or `max_steps`. Collective.
[[nodiscard]] PlasmaFlow steady_plasma_flow(const StenosisCellConfig& c, const common::UnitConverter& units,
                                            double drive_m_s2, double tolerance, long max_steps);

}  // namespace hs::resolved
