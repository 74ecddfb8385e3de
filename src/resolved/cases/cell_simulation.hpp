// SPDX-License-Identifier: MIT
// What every single-RBC coupled case shares: lattice + membrane + CoupledCell, the coupled stages of one step,
// VTK frames, checkpoints and the sampled run loop (tube-cell, shear, migration).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/io/checkpoint.hpp"
#include "common/io/csv_writer.hpp"
#include "common/io/vtk_polydata.hpp"
#include "common/progress.hpp"
#include "common/run_context.hpp"
#include "common/time_loop.hpp"
#include "common/units/unit_converter.hpp"
#include "resolved/cases/cell_numerics.hpp"
#include "resolved/ibm/coupled_cell.hpp"
#include "resolved/ibm/cytoplasm_phase.hpp"
#include "resolved/lbm/fluid_lattice.hpp"
#include "resolved/membrane/membrane_parameters.hpp"
#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

/// One RBC in a lattice fluid. Built in order: units, nodes, origin_m, lattice (by the case: geometry and walls),
/// then add_membrane() and couple().
struct CellSimulation {
  common::UnitConverter units;
  std::array<int, 3> nodes{};
  common::Vec3 origin_m;               // SI position of global lattice node (0, 0, 0)
  std::unique_ptr<FluidLattice> lattice;
  std::unique_ptr<NpfemSolver> membrane;
  std::unique_ptr<CoupledCell> cell;
  std::unique_ptr<CytoplasmPhase> cytoplasm;   // the cytoplasm's own viscosity (viscosity ratio != 1), else null
};

/// The generated (or read) RBC mesh with its disc axis (generated along z) turned to `axis` (0 x, 1 y, 2 z).
[[nodiscard]] TriangleMesh cell_mesh_with_disc_axis(const MembraneConfig& membrane, int axis);
/// The same with the disc axis along y, then turned by `tilt_rad` about x toward z (tube-cell's disc_tilt_deg).
[[nodiscard]] TriangleMesh cell_mesh_tilted_from_y(const MembraneConfig& membrane, double tilt_rad);

/// The subdivided sphere with the vertex count of [membrane]'s mesh, scaled to the volume of a sphere of `radius_m`:
/// a capsule whose rest (and stress-free) shape is that sphere.
[[nodiscard]] TriangleMesh sphere_cell_mesh(const MembraneConfig& membrane, double radius_m);

/// Creates the npFEM solver (material density scaled by n.membrane_mass_factor, step membrane_every dt) with its
/// centroid at `centroid_m`, then the CoupledCell (median filter on, as Palabos-npFEM). With n.viscosity_ratio != 1
/// the lattice (initialised) gets the cytoplasm's relaxation, n.inner_collision, on the nodes the membrane encloses. `add_forces_N`, if given, adds
/// forces to the fluid traction before each membrane step (CouplingSettings::add_forces_N).
void add_coupled_cell(CellSimulation& s, const TriangleMesh& mesh, const MembraneConfig& membrane, const CellNumerics& n,
                      const common::Vec3& centroid_m,
                      std::function<void(std::span<const common::Vec3>, std::vector<common::Vec3>&)> add_forces_N = {});

/// The membrane solver's convergence record for summary.json: steps, iterations per step, unconverged steps and why.
[[nodiscard]] nlohmann::json membrane_solve_summary(const NpfemStatistics& stats);

/// #26's bar for the membrane solve: npFEM reaches its tolerance (or the objective's round-off) on at least this share
/// of its steps in every run.
inline constexpr double kMembraneConvergedShare = 0.99;

/// Adds "the membrane solve converges on >= 99 % of its steps" to `checks`, from a membrane_solve_summary (`label`
/// names the stage where a run has two). Skipped when the run made no membrane step, and when a `quick` run misses the
/// bar: its few hundred steps are mostly the start, where the cell first meets the flow, so they cannot say what share
/// a run leaves unconverged (the rule of every --quick check: too short to decide is skipped, never passed).
void expect_membrane_converged(common::CheckList& checks, const nlohmann::json& membrane_solve, bool quick,
                               const std::string& label = "");

/// summary.json's `groups` of a cell case: the dimensionless groups among its results (Re, Ca, Re_p, gamma+, u_r+, r*,
/// confinement, as the case has them). The results keep them too, beside the values measured with them: the campaign
/// columns and the archived runs read them there (`/results/gamma_plus`).
[[nodiscard]] nlohmann::json groups_of(const nlohmann::json& results);

/// `x_m` (a membrane's vertices) moved by whole periods along the periodic axes so that its centroid lies in the
/// lattice box [origin, origin + nodes dx): the cell travels on unwrapped coordinates (the time series keep them),
/// its VTK frames are drawn where the fluid is. The mesh moves as one, so no triangle is split.
[[nodiscard]] std::vector<common::Vec3> wrapped_into_box(std::vector<common::Vec3> x_m, const common::Vec3& origin_m,
                                                         const std::array<int, 3>& nodes, double dx_m,
                                                         const std::array<bool, 3>& periodic);

/// Marks the nodes the cell's markers enclose as the cytoplasm (no-op without one). All ranks call.
void update_cytoplasm(CellSimulation& s);

/// The coupled stages of one lattice step, in Palabos-npFEM order (resolved-methods.md 2.3), named for the timers.
/// With a cytoplasm, `cytoplasm_indicator` follows membrane_solve: at the start of each membrane interval it marks the
/// nodes the markers enclose (they move less than a node per interval; updating then keeps resumed runs bit for bit).

void add_coupled_stages(common::TimeLoop& loop, CellSimulation& s);

/// Smooth switch-on 0 -> 1 over `steps` steps, (1 - cos(pi step / steps)) / 2: a sudden drive at large tau overshoots
/// (the lattice stress lags the forcing by ~tau steps).
[[nodiscard]] double smooth_ramp(long step, long steps);

/// Writes the membrane (.vtp) and, when fluid_pvd is given, the lattice (.vti) frames; all ranks call, rank 0 writes.
void write_cell_frames(const CellSimulation& s, const common::RunContext& ctx, int frame, common::PvdSeries* membrane_pvd,
                       common::PvdSeries* fluid_pvd);

/// Rank 0's output files (null on the other ranks): timeseries.csv, membrane.pvd, fields.pvd.
struct CellOutputs {
  std::unique_ptr<common::CsvWriter> csv;
  std::unique_ptr<common::PvdSeries> membrane_pvd;
  std::unique_ptr<common::PvdSeries> fluid_pvd;

  void row(const std::vector<double>& values) const {
    if (csv) csv->row(values);
  }
  /// Writes the next frame (membrane and fluid); all ranks call.
  void write_frame(const CellSimulation& s, const common::RunContext& ctx, int& frame) const {
    write_cell_frames(s, ctx, frame++, membrane_pvd.get(), fluid_pvd.get());
  }
};

/// Opens the outputs with the time-series `columns` (rank 0): `series_file` in the run folder, and with `frames` the
/// membrane and fluid ParaView series (a later stage of a run writes a time series of its own and no frames).
[[nodiscard]] CellOutputs open_cell_outputs(const common::RunContext& ctx, const std::vector<std::string>& columns,
                                            std::string_view series_file = "timeseries.csv", bool frames = true);

/// Everything needed to continue bit for bit: populations, force field, membrane, markers and the case's packed
/// samples (one file per rank), written atomically; `stage` (1 unless a case runs stages, as tube-cell's
/// half-time-step stage) is kept in the header.
void write_cell_checkpoint(const CellSimulation& s, std::span<const double> samples, const common::RunContext& ctx,
                           long step, int frame, int stage = 1);

/// The stage whose state the run folder's checkpoint holds (1 for checkpoints written before stages existed).
[[nodiscard]] int checkpoint_stage(const common::RunContext& ctx);

/// Restores write_cell_checkpoint(): fills `samples` and `frame`, returns the step to continue from.
long read_cell_checkpoint(CellSimulation& s, std::vector<double>& samples, const common::RunContext& ctx, int& frame);

/// What the sampled loop calls back.
struct SampledRunHooks {
  std::function<void()> sample;                      // after each block of sample_every steps, on all ranks
  std::function<bool()> done;                        // stop early (e.g. settled); may be empty
  std::function<std::vector<double>()> pack;         // the case's samples for checkpoints
  int checkpoint_stage = 1;                          // written into each checkpoint's header (write_cell_checkpoint)
};

/// Runs `loop` in blocks of `sample_every_steps` until its end or hooks.done(): lattice watchdog, sample, progress,
/// a checkpoint every `checkpoint_every_wall_s` of wall time (rank 0's clock decides) and one at the end.
/// Returns whether done() stopped it.
bool run_sampled(common::TimeLoop& loop, CellSimulation& s, const common::RunContext& ctx, long sample_every_steps,
                 double checkpoint_every_wall_s, common::Progress& progress, const SampledRunHooks& hooks, const int& frame);

}  // namespace hs::resolved
