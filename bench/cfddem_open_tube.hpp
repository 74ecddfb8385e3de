// SPDX-License-Identifier: MIT
// `hemoscale bench cfddem`, open tube: the tube-open case's solvers (velocity inlet, pressure outlet, cells injected
// at the inlet and removed at the outlet) filled with N RBC spheres; s per CFD step and peak RSS, each size measured
// in a child process of its own.
#pragma once

#include <nlohmann/json.hpp>

namespace hs::bench {

/// Set (to the number of cells) only in the child process measure_open_tube_in_child() starts: `hemoscale bench
/// cfddem` then measures that one open-tube size and writes its JSON to --json instead of running the bench.
inline constexpr const char* open_tube_child_env = "HS_BENCH_CFDDEM_OPEN_TUBE_CELLS";

/// The set-up every size shares (for the JSON and the log).
[[nodiscard]] nlohmann::json open_tube_setup_json();

/// In this process: a 100 um open tube at Ht 0.10 holding `n_cells`, filled by volume insertion, warm-up steps, then
/// `repetitions` timed CFD steps (median), with injection and removal active. The peak RSS is this process's.
[[nodiscard]] nlohmann::json measure_open_tube(long n_cells, int repetitions);

/// The same in a fresh process (this executable again, with open_tube_child_env set; OMPI_/PMIX_ variables left out
/// so that it starts as an MPI singleton of its own), so its VmHWM is the size's own and not the largest size's seen
/// so far. Adds the child's wall time (`wall_s`, set-up included). Throws std::runtime_error if the child fails.
[[nodiscard]] nlohmann::json measure_open_tube_in_child(long n_cells);

}  // namespace hs::bench
