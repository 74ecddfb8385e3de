// SPDX-License-Identifier: MIT
// The FVM grid on z-slabs (issue #28, step 1 of docs/cfd-dem.md "Distributed CFD-DEM") at np 1, 2 and 4: each
// block's geometry is the whole grid's, sliced, bit for bit: node kinds, prescribed values (the inlet's profile scaled
// to its flow rate included), apertures, open areas, fluid fractions, the ghost planes the neighbouring blocks send,
// and the wall links of every active node. The whole grid, built on every rank without slabs, is the reference.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "common/geometry/opening_condition.hpp"
#include "common/geometry/tube.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "unresolved/fvm/fvm_grid.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {
namespace {

// The tube-pries grid of `validate pries` at D = 30 um: 10 cells across, 2 diameters long (20 planes: 5 a block at
// np 4). The tube is narrower than the box and tilted, so every plane cuts it differently: a block that read a wrong
// plane (its own instead of its neighbour's, or one off) would be seen.
constexpr double kDiameter = 30e-6;
constexpr double kLength = 60e-6;
constexpr int kAcross = 10;
constexpr hs::common::Vec3 kStart{-3e-6, -1e-6, 0.0};
constexpr hs::common::Vec3 kEnd{3e-6, 2e-6, kLength};
constexpr double kRadius = 0.4 * kDiameter;

hs::common::Tube tube() { return hs::common::Tube({.start_m = kStart, .end_m = kEnd, .radius_m = kRadius}); }

FvmGridSpec spec(bool open) {
  const double r = 0.5 * kDiameter;
  FvmGridSpec s{.box_m = {{-r, -r, 0.0}, {r, r, kLength}}, .dx_m = kDiameter / kAcross, .sides = {}};
  if (!open) {
    s.sides[4].type = SideType::periodic;
    s.sides[5].type = SideType::periodic;
    return s;
  }
  // The open tube: a flow-rate inlet at z = 0 and a pressure outlet at z = L (cases/unresolved/tube-open's kind).
  const hs::common::Opening in{.name = "in", .kind = hs::common::OpeningKind::inlet, .centre_m = kStart,
                               .normal = {0, 0, -1}, .radius_m = kRadius};
  const hs::common::Opening out{.name = "out", .kind = hs::common::OpeningKind::outlet, .centre_m = kEnd,
                                .normal = {0, 0, 1}, .radius_m = kRadius};
  s.openings = {hs::common::flow_rate_inlet(in, std::numbers::pi * kRadius * kRadius * 1e-3),
                hs::common::pressure_outlet(out, 0.0)};
  return s;
}

/// Points of `field` on this block (ghosts included) that differ from the whole grid's at the same global place.
template <typename T>
int differences(const BlockField<T>& block, const BlockField<T>& whole, int first_plane) {
  const auto& n = block.cells();
  int count = 0;
  for (int k = -1; k <= n[2] + 1; ++k) {
    for (int j = -1; j <= n[1] + 1; ++j) {
      for (int i = -1; i <= n[0] + 1; ++i) {
        if (block(i, j, k) != whole(i, j, first_plane + k)) ++count;
      }
    }
  }
  return count;
}

int link_differences(const FvmGrid& block, const FvmGrid& whole, int c) {
  int count = 0;
  for (int k = 0; k < block.node_count(c, 2); ++k) {
    for (int j = 0; j < block.node_count(c, 1); ++j) {
      for (int i = 0; i < block.node_count(c, 0); ++i) {
        if (block.kind(c, i, j, k) != NodeKind::active) continue;
        for (int dir = 0; dir < 6; ++dir) {
          const NodeLink a = block.link(c, {i, j, k}, dir);
          const NodeLink b = whole.link(c, {i, j, block.first_plane() + k}, dir);
          if (a.type != b.type || a.theta != b.theta || a.value != b.value) ++count;
        }
      }
    }
  }
  return count;
}

/// The whole grid (on every rank) and this rank's z-slab of it, over the same tube.
struct WholeAndBlock {
  explicit WholeAndBlock(bool open)
      : s(spec(open)), whole(shape, s),
        slabs({.global_nodes = whole.cells(), .periodic = {false, false, !open}, .ranks_per_axis = {1, 1, 0}, .ghost = 2},
              MPI_COMM_WORLD),
        block(shape, s, &slabs) {}
  hs::common::Tube shape = tube();
  FvmGridSpec s;
  FvmGrid whole;
  hs::common::CartesianDecomposition slabs;
  FvmGrid block;
};

void expect_the_whole_grid_sliced(bool open) {
  const WholeAndBlock grids(open);
  const FvmGrid& whole = grids.whole;
  const FvmGrid& block = grids.block;
  const hs::common::CartesianDecomposition& slabs = grids.slabs;
  ASSERT_EQ(block.first_plane(), slabs.offset()[2]);
  ASSERT_EQ(block.global_cells(), whole.cells());
  const int first = block.first_plane();
  int mine = differences(block.fluid_fractions(), whole.fluid_fractions(), first);
  for (int c = 0; c < 3; ++c) {
    mine += differences(block.kinds(c), whole.kinds(c), first);
    mine += differences(block.fixed_values(c), whole.fixed_values(c), first);
    mine += differences(block.apertures(c), whole.apertures(c), first);
    mine += differences(block.open_areas(c), whole.open_areas(c), first);
    mine += link_differences(block, whole, c);
  }
  int all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(all, 0);
  // Each block owns its nodes once: the face nodes of component z over all blocks are the whole grid's.
  int faces = block.node_count(2, 2);
  int total = 0;
  MPI_Allreduce(&faces, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, whole.node_count(2, 2));
}

TEST(FvmGridSlabs, ThePeriodicTubeIsTheWholeGridSliced) { expect_the_whole_grid_sliced(false); }

TEST(FvmGridSlabs, TheOpenTubeIsTheWholeGridSlicedInletProfileIncluded) { expect_the_whole_grid_sliced(true); }

TEST(FvmGridSlabs, ACellFieldsGhostsAreTheWholeGridsOnEveryBlock) {
  // fill_cell_field_ghosts (the coupling's fields): periodic wrap or zero gradient on the box, the neighbouring
  // blocks' planes between blocks; on both tubes equal to the whole grid's ghosts bit for bit.
  for (const bool open : {false, true}) {
    const WholeAndBlock grids(open);
    const FvmGrid& whole = grids.whole;
    const FvmGrid& block = grids.block;
    const auto value = [](int i, int j, int k) { return 1.0 + 0.1 * i + 0.01 * j + 0.001 * k * k; };
    BlockField<double> w(whole.cells(), -1.0), b(block.cells(), -1.0);
    for (int k = 0; k < whole.cells()[2]; ++k) {
      for (int j = 0; j < kAcross; ++j) {
        for (int i = 0; i < kAcross; ++i) w(i, j, k) = value(i, j, k);
      }
    }
    for (int k = 0; k < block.cells()[2]; ++k) {
      for (int j = 0; j < kAcross; ++j) {
        for (int i = 0; i < kAcross; ++i) b(i, j, k) = value(i, j, block.first_plane() + k);
      }
    }
    fill_cell_field_ghosts(whole, w);
    fill_cell_field_ghosts(block, b);
    // Planes -1 .. n of the block (n + 1 is a face grid's extra plane, not a cell field's ghost).
    int mine = 0;
    for (int k = -1; k <= block.cells()[2]; ++k) {
      for (int j = -1; j <= kAcross; ++j) {
        for (int i = -1; i <= kAcross; ++i) mine += b(i, j, k) != w(i, j, block.first_plane() + k) ? 1 : 0;
      }
    }
    int all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(all, 0) << (open ? "open" : "periodic");
  }
}

/// The largest |block - whole| over this block's face nodes (ghosts included) and over its cells' pressures, each
/// over the whole grid's largest magnitude of that field; the maximum over the ranks.
double largest_relative_difference(const FvmSolver& block, const FvmSolver& whole) {
  const int first = block.grid().first_plane();
  const auto& n = block.grid().cells();
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto& b = block.face_velocity(c);
    const auto& w = whole.face_velocity(c);
    double scale = 0.0;
    for (const double v : w.data()) scale = std::max(scale, std::abs(v));
    for (int k = -1; k <= n[2] + 1; ++k) {
      for (int j = -1; j <= n[1] + 1; ++j) {
        for (int i = -1; i <= n[0] + 1; ++i) worst = std::max(worst, std::abs(b(i, j, k) - w(i, j, first + k)) / scale);
      }
    }
  }
  double p_scale = 0.0;
  const auto& nw = whole.grid().cells();
  for (int k = 0; k < nw[2]; ++k) {
    for (int j = 0; j < nw[1]; ++j) {
      for (int i = 0; i < nw[0]; ++i) p_scale = std::max(p_scale, std::abs(whole.cell_pressure_Pa(i, j, k)));
    }
  }
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        worst = std::max(worst, std::abs(block.cell_pressure_Pa(i, j, k) - whole.cell_pressure_Pa(i, j, first + k)) / p_scale);
      }
    }
  }
  double all = 0.0;
  MPI_Allreduce(&worst, &all, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return all;
}

TEST(FvmGridSlabs, TheSolverOnBlocksFollowsTheWholeGrid) {
  // The plasma alone over 100 steps, both tubes (the periodic one held at a flow rate, the open one between its inlet
  // and outlet), each rank's block against the whole grid solved on every rank alone. At one rank the block takes the
  // distributed paths (ghost planes through exchange_halo, the periodic wrap through MPI; sums through MPI) and must
  // follow the whole grid bit for bit. On several ranks the AMG preconditioner differs (coarsening and smoothing per
  // rank), so both solve to 1e-12: each step's fields then differ by up to cond x 1e-12 (cond ~ 1e3 for the pressure
  // matrix of this 10 x 10 x 20 grid), and 100 steps of a dissipative flow do not amplify it: 1e-9 of the fields'
  // largest values (measured: 1.1e-13 to 4.5e-13 at np 2 and 4).
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  for (const bool open : {false, true}) {
    const WholeAndBlock grids(open);
    const FluidProperties plasma{.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6};
    // Viscous number nu dt / dx^2 = 1.3, Courant ~ 0.01; tight solves (see above).
    const PisoSettings piso{.dt_s = 1e-5, .pressure = {.tolerance = 1e-12, .rel_tol = 0.0, .max_iterations = 1000},
                            .momentum_tolerance = 1e-12};
    FlowDrive drive{};
    if (!open) {
      drive = {.mode = FlowDrive::Mode::flow_rate, .axis = 2,
               .flow_rate_m3_s = std::numbers::pi * kRadius * kRadius * 1e-3};
    }
    FvmSolver whole(grids.whole, plasma, piso, drive, MPI_COMM_SELF);
    FvmSolver block(grids.block, plasma, piso, drive, MPI_COMM_WORLD);
    for (int s = 0; s < 100; ++s) {
      whole.step();
      block.step();
    }
    const double difference = largest_relative_difference(block, whole);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::printf("%s tube, %d ranks: largest relative difference %.3g\n", open ? "open" : "periodic", size, difference);
    if (size == 1) {
      EXPECT_EQ(difference, 0.0) << (open ? "open" : "periodic");
    } else {
      EXPECT_LE(difference, 1e-9) << (open ? "open" : "periodic");
    }
    EXPECT_NEAR(block.flow_rate_m3_s(2), whole.flow_rate_m3_s(2), 1e-9 * std::abs(whole.flow_rate_m3_s(2)));
    EXPECT_GT(std::abs(whole.flow_rate_m3_s(2)), 0.0);
  }
}


TEST(FvmGridSlabs, SamplingNearBlockFacesIsTheWholeGrids) {
  // What the coupling reads at a particle (velocity, its gradient, the pressure gradient, the viscous force density)
  // at points within half a cell of this block's faces, inside it, against the whole grid after 20 steps of the
  // periodic tube at solver tolerance 1e-12 (fields within 1e-9 of each other, FvmGridSlabs test above): the same to
  // that band, relative to each quantity's largest magnitude over the points.
  const WholeAndBlock grids(false);
  const FluidProperties plasma{.density_kg_m3 = 1025.0, .kinematic_viscosity_m2_s = 1.2e-6};
  const PisoSettings piso{.dt_s = 1e-5, .pressure = {.tolerance = 1e-12, .rel_tol = 0.0, .max_iterations = 1000},
                          .momentum_tolerance = 1e-12};
  const FlowDrive drive{.mode = FlowDrive::Mode::flow_rate, .axis = 2,
                        .flow_rate_m3_s = std::numbers::pi * kRadius * kRadius * 1e-3};
  FvmSolver whole(grids.whole, plasma, piso, drive, MPI_COMM_SELF);
  FvmSolver block(grids.block, plasma, piso, drive, MPI_COMM_WORLD);
  for (int s = 0; s < 20; ++s) {
    whole.step();
    block.step();
  }
  const double h = grids.whole.dx_m();
  const double lo = grids.block.origin_m().z;
  const double hi = lo + grids.block.cells()[2] * h;
  std::array<double, 4> worst{}, scale{};
  for (const double z : {lo, lo + 0.25 * h, lo + 0.49 * h, lo + 0.5 * h, hi - 0.5 * h, hi - 0.49 * h, hi - 0.25 * h,
                         hi - 1e-3 * h}) {
    for (int q = 0; q < 9; ++q) {   // across the tube's section
      const hs::common::Vec3 x{(q % 3 - 1) * 0.3 * kRadius + kStart.x, (q / 3 - 1) * 0.3 * kRadius + kStart.y, z};
      const auto gb = block.velocity_gradient_at(x);
      const auto gw = whole.velocity_gradient_at(x);
      double dg = 0.0, sg = 0.0;
      for (int a = 0; a < 3; ++a) {
        dg = std::max(dg, norm(gb[static_cast<std::size_t>(a)] - gw[static_cast<std::size_t>(a)]));
        sg = std::max(sg, norm(gw[static_cast<std::size_t>(a)]));
      }
      const std::array<double, 4> d{norm(block.velocity_at(x) - whole.velocity_at(x)), dg,
                                    norm(block.pressure_gradient_at(x) - whole.pressure_gradient_at(x)),
                                    norm(block.viscous_force_density_at(x) - whole.viscous_force_density_at(x))};
      const std::array<double, 4> m{norm(whole.velocity_at(x)), sg, norm(whole.pressure_gradient_at(x)),
                                    norm(whole.viscous_force_density_at(x))};
      for (std::size_t k = 0; k < 4; ++k) {
        worst[k] = std::max(worst[k], d[k]);
        scale[k] = std::max(scale[k], m[k]);
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, worst.data(), 4, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char* names[] = {"velocity", "velocity gradient", "pressure gradient", "viscous force density"};
  for (std::size_t k = 0; k < 4; ++k) {
    if (rank == 0) std::printf("near block faces: %s differs by %.3g of its largest value\n", names[k], worst[k] / scale[k]);
    EXPECT_LE(worst[k], 1e-9 * scale[k]) << names[k];
  }
}

}  // namespace
}  // namespace hs::unresolved
