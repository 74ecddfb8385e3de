// SPDX-License-Identifier: MIT
// The lattice's second fluid phase (the cytoplasm): its relaxation, its nodes, and the runs split by phase.
#include "resolved/lbm/fluid_lattice.hpp"

#include <stdexcept>

namespace hs::resolved {

void FluidLattice::set_inner_collision(const CollisionParams& inner) {
  inner.validate();
  inner_collision_ = inner;
  inner_relaxation_ = PhaseRelaxation{.omega_plus = inner.omega_plus(), .omega_minus = inner.omega_minus(),
                                      .regularized = inner.regularizes()};
}

/// The runs are rebuilt from the geometry's (kept at the first call) each time: O(fluid nodes) in bytes, once per
/// membrane step, against 19 x 2 doubles per node each lattice step.
void FluidLattice::set_inner_nodes(std::span<const std::ptrdiff_t> nodes) {
  if (!inner_collision_) throw std::logic_error("FluidLattice::set_inner_nodes: set_inner_collision() first");
  if (runs_.empty() && fluid_nodes_ > 0) throw std::logic_error("FluidLattice::set_inner_nodes: initialize() first");
  if (phase_.empty()) {
    phase_.assign(layout_.volume(), 0);
    geometry_runs_ = runs_;
  }
  for (const std::ptrdiff_t n : inner_nodes_) phase_[static_cast<std::size_t>(n)] = 0;
  inner_nodes_.clear();
  for (const std::ptrdiff_t n : nodes) {
    const auto k = static_cast<std::size_t>(n);
    if (k >= flags_.size() || flags_[k] != kFluid || phase_[k] != 0) continue;
    phase_[k] = 1;
    inner_nodes_.push_back(n);
  }
  std::vector<FluidRun> split;
  split.reserve(geometry_runs_.size() + 2 * inner_nodes_.size());
  for (const FluidRun& run : geometry_runs_) {
    std::ptrdiff_t n = run.begin;
    const std::ptrdiff_t end = run.begin + run.length;
    while (n < end) {
      const std::uint8_t phase = phase_[static_cast<std::size_t>(n)];
      const std::ptrdiff_t start = n;
      while (n < end && phase_[static_cast<std::size_t>(n)] == phase) ++n;
      split.push_back(FluidRun{.begin = start,
                               .length = n - start,
                               .odd_parts = run.odd_parts >= 0 ? run.odd_parts + (start - run.begin) : -1,
                               .phase = phase});
    }
  }
  runs_ = std::move(split);
  if (aa()) index_layer_runs();
}

}  // namespace hs::resolved
