// SPDX-License-Identifier: MIT
// The momentum-consistent coupling (MembraneForce::ibm_reaction): in a fully periodic box without walls or drive the
// momentum of fluid + membrane is conserved to round-off; the stress-sampling coupling does not conserve it.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/lbm/d3q19.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

constexpr int kBox = 20;
constexpr double kDx = 1.0e-6;
constexpr double kTau = 8.0;   // nu_lu = 2.5: large enough that npFEM steps start from x_n (see below)
constexpr double kNu = 1.0e-6;
constexpr double kU0 = 0.01;    // uniform stream, lattice units: the cell starts at rest in it
constexpr double kDu = 0.005;   // plus a shear wave u_x = kDu sin(2 pi y / L) that deforms and turns it

struct Box {
  common::UnitConverter units = common::UnitConverter::from_relaxation_time(kDx, kTau, kNu, 1025.0);
  std::unique_ptr<FluidLattice> lattice;
  std::unique_ptr<NpfemSolver> membrane;
  std::unique_ptr<CoupledCell> cell;
};

std::unique_ptr<Box> make_box(MembraneForce force, double mass_factor, int max_iterations) {
  auto b = std::make_unique<Box>();
  b->lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {kBox, kBox, kBox}, .periodic = {true, true, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = kTau}},
      MPI_COMM_WORLD);
  b->lattice->enable_force_field();
  b->lattice->initialize([](const Vec3& x) {
    return NodeInit{.rho_lu = 1.0, .u_lu = {kU0 + kDu * std::sin(2.0 * std::numbers::pi * x.y / kBox), 0.0, 0.0}};
  });
  MembraneParameters material;
  material.density_kg_m3 *= mass_factor;
  NpfemSettings solver;
  solver.max_iterations = max_iterations;
  const int k = 2;
  b->membrane = std::make_unique<NpfemSolver>(make_rbc_mesh({}), material, solver, k * b->units.dt_s());
  b->membrane->translate_m(Vec3{9.3, 10.1, 9.7} * kDx - b->membrane->centroid_m());
  b->cell = std::make_unique<CoupledCell>(
      *b->lattice, *b->membrane, b->units,
      CouplingSettings{.ibm = {.kernel = DeltaKernel::two_point, .iterations = 3}, .membrane_every = k,
                       .median_filter = true, .membrane_force = force, .lattice_origin_m = {}});
  return b;
}

/// Sum over the nodes of sum_i f_i c_i (pre-collision populations): a step with the force field F changes it by
/// exactly sum F (Guo forcing), so this is the momentum the IBM forces are accounted against.
Vec3 fluid_momentum_lu(const FluidLattice& lattice) {
  Vec3 p;
  const auto& n = lattice.layout().n;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const Populations f = lattice.populations(x, y, z);
        for (int i = 0; i < D3Q19::q; ++i) {
          const auto iu = static_cast<std::size_t>(i);
          p += f[iu] * Vec3{static_cast<double>(D3Q19::c[iu][0]), static_cast<double>(D3Q19::c[iu][1]),
                            static_cast<double>(D3Q19::c[iu][2])};
        }
      }
  MPI_Allreduce(MPI_IN_PLACE, &p.x, 3, MPI_DOUBLE, MPI_SUM, lattice.decomposition().comm());
  return p;
}

Vec3 membrane_momentum_lu(const Box& b) {
  Vec3 p;
  for (const Vec3& v : b.membrane->velocities_m_s()) p += v;
  const double momentum_scale = b.units.to_si_force(1.0) * b.units.dt_s();   // kg m/s per lattice momentum unit
  return (b.membrane->vertex_mass_kg() / momentum_scale) * p;
}

/// Fluid + membrane momentum, minus the impulse the fluid has received and the membrane will get at its next step.
Vec3 total_momentum_lu(const Box& b) {
  Vec3 pending;
  for (const Vec3& r : b.cell->state().reaction_lu) pending += r;
  return fluid_momentum_lu(*b.lattice) + membrane_momentum_lu(b) - pending;
}

struct Drift {
  double max_relative = 0.0;      // max over steps of |P - P0| / |P0|
  double membrane_share = 0.0;    // |P_membrane| / |P0| at the end: how much momentum went over to the cell
};

Drift run(MembraneForce force, double mass_factor, int steps, int max_iterations = 30) {
  auto b = make_box(force, mass_factor, max_iterations);
  const Vec3 p0 = total_momentum_lu(*b);
  Drift d;
  for (int n = 0; n < steps; ++n) {
    b->cell->step();
    d.max_relative = std::max(d.max_relative, common::norm(total_momentum_lu(*b) - p0) / common::norm(p0));
  }
  d.membrane_share = common::norm(membrane_momentum_lu(*b)) / common::norm(p0);
  return d;
}

// The cell (mass factor 10, as the cases' 1.25 nu_lu k at tau ~ 8; 5 was the lightest stable here, see
// docs/resolved-coupling.md) starts at rest in the stream and is carried along. Measured (2-point kernel, 3 iterations,
// k = 2, 300 steps): ibm_reaction |P - P0| / |P0| <= 5e-13, the plain lattice's own floor (its momentum sum moves
// by 2-3e-11 = 4e-13 of P0 per step without any force); without NpfemSolver::set_exact_translation 5e-7 (npFEM
// steps that start from x_n and stop early); with npFEM capped at 3 iterations the same. fluid_stress: 0.15 (0.10 at
// tau 2; printed, not asserted: it is the defect being fixed).
TEST(ReactionCoupling, ConservesFluidPlusMembraneMomentumInAPeriodicBox) {
  const Drift reaction = run(MembraneForce::ibm_reaction, 10.0, 300);
  const Drift capped = run(MembraneForce::ibm_reaction, 10.0, 300, 3);   // npFEM stopped at 3 iterations every step
  const Drift stress = run(MembraneForce::fluid_stress, 10.0, 300);
  std::printf("[reaction] max |P - P0| / |P0| over 300 steps: ibm_reaction %.3e (npFEM cap 3: %.3e), fluid_stress "
              "%.3e; membrane momentum at the end / P0: %.4f, %.4f\n",
              reaction.max_relative, capped.max_relative, stress.max_relative, reaction.membrane_share,
              stress.membrane_share);
  EXPECT_LT(reaction.max_relative, 1e-11);   // 20x the lattice's floor
  EXPECT_LT(capped.max_relative, 1e-11);
  // Not trivial: the cell is carried along. Its mass (x10) is 12.6 % of the box's fluid, so at a common velocity it
  // holds 0.126 / 1.126 = 0.112 of the momentum.
  EXPECT_NEAR(reaction.membrane_share, 0.112, 0.01);
}

/// Energy bookkeeping of a stretched cell relaxing in fluid at rest (joules, summed over the run).
struct PowerBalance {
  double fluid_work_J = 0.0;       // work the fluid does on the membrane, from the fluid side: -sum_x F_ibm . u dt
  double marker_work_J = 0.0;      // the same at the markers' velocities: -sum_k F_k . U_k dt
  double membrane_work_J = 0.0;    // work of the membrane's external force: sum over npFEM steps of h f . v^{n+1}
  double membrane_energy_J = 0.0;  // change of elastic + kinetic energy of the membrane
  double step_dissipation_J = 0.0; // implicit Euler's own loss, sum of m |v^{n+1} - v^n|^2 / 2
  double released_J = 0.0;         // elastic energy at the start minus at the end
};

PowerBalance relax_stretched_cell(MembraneForce force, int steps) {
  auto b = std::make_unique<Box>();
  b->lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {kBox, kBox, kBox}, .periodic = {true, true, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = kTau}},
      MPI_COMM_WORLD);
  b->lattice->enable_force_field();
  b->lattice->initialize();
  MembraneParameters material;
  material.density_kg_m3 *= 10.0;
  material.shear_modulus_N_m *= 10.0;   // so that it relaxes visibly within the run (default friction 2.82e4 Pa s/m)
  material.rayleigh_beta_s = 0.0;       // dissipation: the friction (counted by npFEM) and the implicit step's own
  const int k = 2;
  const double h_s = k * b->units.dt_s();
  b->membrane = std::make_unique<NpfemSolver>(make_rbc_mesh({}), material, NpfemSettings{}, h_s);
  b->membrane->translate_m(Vec3{9.3, 10.1, 9.7} * kDx - b->membrane->centroid_m());
  std::vector<double> st = b->membrane->state();   // positions first (um): stretch 15 % along x, squeeze along y
  const Vec3 c_um = 1e6 * b->membrane->centroid_m();
  for (std::size_t v = 0; v < static_cast<std::size_t>(b->membrane->vertex_count()); ++v) {
    st[3 * v] = c_um.x + 1.15 * (st[3 * v] - c_um.x);
    st[3 * v + 1] = c_um.y + (st[3 * v + 1] - c_um.y) / 1.15;
  }
  b->membrane->restore_state(std::span<const double>(st).first(9 * static_cast<std::size_t>(b->membrane->vertex_count()) + 3));
  b->cell = std::make_unique<CoupledCell>(
      *b->lattice, *b->membrane, b->units,
      CouplingSettings{.ibm = {.kernel = DeltaKernel::two_point, .iterations = 3}, .membrane_every = k,
                       .median_filter = true, .membrane_force = force, .lattice_origin_m = {}});
  const double m_kg = b->membrane->vertex_mass_kg();
  const auto kinetic = [&] {
    double e = 0.0;
    for (const Vec3& v : b->membrane->velocities_m_s()) e += 0.5 * m_kg * common::dot(v, v);
    return e;
  };
  const double power_scale_W = b->units.to_si_force(1.0) * b->units.to_si_velocity(1.0);
  const double e0_el = b->membrane->elastic_energy_J();
  const double e0 = e0_el + kinetic();
  PowerBalance p;
  const auto& n = b->lattice->layout().n;
  for (int step = 0; step < steps; ++step) {
    if (step % k == 0) {   // the force this npFEM step will apply: what the stage computes from the pending reaction
      const auto v0 = b->membrane->velocities_m_s();
      b->cell->membrane_solve();
      const auto v1 = b->membrane->velocities_m_s();
      const auto f = b->membrane->state();   // external forces follow positions and velocities (pN)
      const std::size_t nv = v1.size();
      for (std::size_t v = 0; v < nv; ++v) {
        const Vec3 f_N = 1e-12 * Vec3{f[6 * nv + 3 * v], f[6 * nv + 3 * v + 1], f[6 * nv + 3 * v + 2]};
        p.membrane_work_J += h_s * common::dot(f_N, v1[v]);
        p.step_dissipation_J += 0.5 * m_kg * common::dot(v1[v] - v0[v], v1[v] - v0[v]);
      }
    } else {
      b->cell->membrane_solve();
    }
    b->cell->ibm_forcing();
    const auto& fk = b->cell->report().forcing.marker_force_lu;
    const auto uk = b->cell->state().marker_u_lu;
    for (std::size_t v = 0; v < fk.size(); ++v) p.marker_work_J -= common::dot(fk[v], uk[v]) * power_scale_W * b->units.dt_s();
    double power_lu = 0.0;   // F . u at the half-force velocity: the rate the IBM force works on the fluid
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) power_lu += common::dot(b->lattice->force(x, y, z), b->lattice->moments(x, y, z).u);
    MPI_Allreduce(MPI_IN_PLACE, &power_lu, 1, MPI_DOUBLE, MPI_SUM, b->lattice->decomposition().comm());
    p.fluid_work_J -= power_lu * power_scale_W * b->units.dt_s();
    b->cell->lbm_step();
    b->cell->markers_advect();
  }
  const double e1_el = b->membrane->elastic_energy_J();
  p.membrane_energy_J = e1_el + kinetic() - e0;

  p.released_J = e0_el - e1_el;
  return p;
}

// Power over the relaxation of a stretched cell (tau 8, 2-point kernel, 3 iterations, k = 2, mass factor 10, k_s x10,
// default friction; 400 steps). Measured, ibm_reaction: the markers do -1.007e-17 J of work on the fluid, the
// membrane's external force -9.54e-18 J (5.3 % apart: the reaction of one interval acts during the next); the fluid
// receives F . u_half = -5.04e-18 J: the direct forcing itself dissipates the other half (each step it resets the
// fluid at the marker impulsively, an inelastic exchange F . (U - u_half) >= 0). fluid_stress: markers -1.07e-17 J,
// membrane -1.13e-18 J (9.5x apart): the fluid receives 4.8x the work the membrane's force did. The membrane released
// 5.0e-16 J of elastic energy, nearly all of it into its friction. docs/resolved-coupling.md, "Power".
TEST(ReactionCoupling, MembraneWorkMatchesTheMarkersWorkOnTheFluid) {
  for (const MembraneForce force : {MembraneForce::ibm_reaction, MembraneForce::fluid_stress}) {
    const PowerBalance p = relax_stretched_cell(force, 400);
    const bool reaction = force == MembraneForce::ibm_reaction;
    std::printf("[power] %s: released %.4e J; fluid work on membrane %.4e J (at the markers %.4e), membrane external "
                "work %.4e J, membrane energy change %.4e J, step loss %.4e J\n",
                reaction ? "ibm_reaction" : "fluid_stress", p.released_J, p.fluid_work_J, p.marker_work_J,
                p.membrane_work_J, p.membrane_energy_J, p.step_dissipation_J);
    if (!reaction) continue;
    EXPECT_GT(p.released_J, 1e-16);                                 // something happened
    EXPECT_NEAR(p.membrane_work_J / p.marker_work_J, 1.0, 0.1);     // the same work, seen from both sides
    EXPECT_GE(p.fluid_work_J, p.marker_work_J);                     // the exchange creates no energy
  }
}

}  // namespace
}  // namespace hs::resolved
