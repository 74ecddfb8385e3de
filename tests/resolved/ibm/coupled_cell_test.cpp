// SPDX-License-Identifier: MIT
// The coupled RBC: a cell at rest in fluid at rest stays put; a fixed cell in a periodic box driven by a body
// force reaches the exact momentum balance (force on the cell = body force times fluid volume).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/membrane/rbc_mesh_generator.hpp"

namespace hs::resolved {
namespace {

using common::Vec3;

constexpr int kBox = 20;
constexpr double kDx = 1.0e-6;    // the campaign resolution: RBC diameter 7.8 lu
constexpr double kTau = 2.0;      // Palabos-npFEM default (resolved-methods.md 1.3)
constexpr double kNu = 1.0e-6;    // plasma

struct Setup {
  common::UnitConverter units = common::UnitConverter::from_relaxation_time(kDx, kTau, kNu, 1025.0);
  std::unique_ptr<FluidLattice> lattice;
  std::unique_ptr<NpfemSolver> membrane;
  std::unique_ptr<CoupledCell> cell;
};

std::unique_ptr<Setup> make_setup(double body_force_lu, CenterConstraint constraint) {
  auto s = std::make_unique<Setup>();
  s->lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = {kBox, kBox, kBox}, .periodic = {true, true, true},
                  .collision = CollisionParams{.model = CollisionModel::trt, .tau = kTau}},
      MPI_COMM_WORLD);
  s->lattice->set_body_force({body_force_lu, 0.0, 0.0});
  s->lattice->enable_force_field();
  s->lattice->initialize();
  const int k = 2;
  s->membrane = std::make_unique<NpfemSolver>(make_rbc_mesh({}), MembraneParameters{}, NpfemSettings{},
                                              k * s->units.dt_s());
  // Centre of the cell at (9.3, 10.1, 9.7) lu, slightly off-node; the disc's axis is z.
  s->membrane->translate_m(Vec3{9.3, 10.1, 9.7} * kDx - s->membrane->centroid_m());
  s->membrane->set_center_constraint(constraint);
  s->cell = std::make_unique<CoupledCell>(*s->lattice, *s->membrane, s->units,
                                          CouplingSettings{.ibm = {}, .membrane_every = k, .median_filter = true, .lattice_origin_m = {}});
  return s;
}

TEST(CoupledCell, CellAtRestStaysAtRest) {
  auto s = make_setup(0.0, CenterConstraint::free);
  const auto x0 = s->membrane->positions_m();
  for (int n = 0; n < 40; ++n) s->cell->step();
  const auto x1 = s->membrane->positions_m();
  double moved = 0.0;
  for (std::size_t v = 0; v < x0.size(); ++v) moved = std::max(moved, common::norm(x1[v] - x0[v]));
  // The mesh is its own rest shape and the fluid is at rest: only round-off may move it (1e-6 lu).
  EXPECT_LT(moved / kDx, 1e-6);
  EXPECT_LT(s->cell->report().marker_drift_lu, 1e-9);
  EXPECT_EQ(s->cell->report().vertices_without_fluid, 0);
}

TEST(CoupledCell, FixedCellBalancesTheBodyForce) {
  const double g_lu = 2.0e-6;
  auto s = make_setup(g_lu, CenterConstraint::fixed);
  const Vec3 c0 = s->membrane->centroid_m();
  for (int n = 0; n < 1600; ++n) s->cell->step();   // ~4 viscous times L^2/nu of the box
  const double driving = g_lu * kBox * kBox * kBox;  // lattice units; the cell's interior is fluid too
  const double ibm = -s->cell->report().forcing.total_force_lu.x;
  const double traction = s->units.to_lattice_force(s->cell->report().fluid_force_N.x);
  std::printf("[coupled] body force %.4e, IBM force on fluid %.4e (ratio %.4f), traction on cell %.4e (ratio %.4f)\n",
              driving, ibm, ibm / driving, traction, traction / driving);
  // At steady state the IBM force must balance the drive exactly; 2% allows for the remaining transient.
  EXPECT_NEAR(ibm / driving, 1.0, 0.02);
  // The default tractions are scaled to the area of the surface through the sample nodes (~2 lu out), so they carry
  // about the IBM force minus the drive on the fluid inside that surface (~5 % of this box) minus the kernel's
  // spread beyond the samples; 0.79 is measured. The membrane's own areas give 0.3-0.5 (docs/resolved-coupling.md):
  // 0.7 tells the two apart.
  EXPECT_GT(traction / driving, 0.7);
  EXPECT_LT(common::norm(s->membrane->centroid_m() - c0) / kDx, 1e-9);
}

}  // namespace
}  // namespace hs::resolved
