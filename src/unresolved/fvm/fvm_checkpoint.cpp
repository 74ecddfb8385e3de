// SPDX-License-Identifier: MIT
// FvmSolver restart: its persistent state into and out of a common::Checkpoint.
#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

std::vector<double> flatten(const BlockField<Vec3>& f) {
  std::vector<double> out;
  out.reserve(3 * f.data().size());
  for (const Vec3& v : f.data()) out.insert(out.end(), {v.x, v.y, v.z});
  return out;
}

const std::vector<double>& sized(const hs::common::Checkpoint& cp, const std::string& name, std::size_t n) {
  const std::vector<double>& v = cp.doubles(name);
  if (v.size() != n) {
    throw hs::common::ConfigError(fmt::format("checkpoint: \"{}\" has {} values, this grid needs {} (a checkpoint of "
                                              "another case or resolution)", name, v.size(), n));
  }
  return v;
}

void restore(const hs::common::Checkpoint& cp, const std::string& name, BlockField<double>& f) {
  f.data() = sized(cp, name, f.data().size());
}

void restore(const hs::common::Checkpoint& cp, const std::string& name, BlockField<Vec3>& f) {
  const std::vector<double>& v = sized(cp, name, 3 * f.data().size());
  for (std::size_t i = 0; i < f.data().size(); ++i) f.data()[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

}  // namespace

void FvmSolver::write_state(hs::common::Checkpoint& cp, const std::string& prefix) const {
  for (std::size_t c = 0; c < 3; ++c) {
    const Eigen::VectorXd& x = comp_[c].x;
    cp.put(fmt::format("{}velocity_{}", prefix, c), std::span<const double>(x.data(), static_cast<std::size_t>(x.size())));
    cp.put(fmt::format("{}flux_{}", prefix, c), phi_[c].data());
  }
  cp.put(prefix + "pressure", p_.data());
  cp.put(prefix + "void_fraction", eps_.data());
  cp.put(prefix + "void_fraction_rate", deps_dt_.data());
  cp.put(prefix + "implicit_coefficient", ksl_.data());
  if (variable_viscosity_) cp.put(prefix + "viscosity_factor", visc_.data());
  cp.put(prefix + "particle_velocity", flatten(us_));
  cp.put(prefix + "explicit_force", flatten(force_));
  const std::vector<double> scalars{time_s_, drive_gradient_};
  cp.put(prefix + "scalars", scalars);
  const std::vector<std::int64_t> steps{steps_};
  cp.put(prefix + "steps", steps);
  // The AMG hierarchy in use: without it a resume would solve with a fresh one where the uninterrupted run keeps
  // its aged one, and the runs would part by the solver tolerance (grown by the DEM's chaos).
  const AmgCheckpoint amg = pressure_.checkpoint();
  cp.put(prefix + "pressure_amg_setup_matrix", amg.setup_values);
  const std::vector<std::int64_t> amg_state{amg.built ? 1 : 0, amg.fresh_iterations, amg.fresh ? 1 : 0,
                                            amg.stale ? 1 : 0, amg.setups, amg.reuses};
  cp.put(prefix + "pressure_amg_state", amg_state);
}

void FvmSolver::read_state(const hs::common::Checkpoint& cp, const std::string& prefix) {
  for (std::size_t c = 0; c < 3; ++c) {
    Component& comp = comp_[c];
    const std::vector<double>& x = sized(cp, fmt::format("{}velocity_{}", prefix, c), static_cast<std::size_t>(comp.x.size()));
    comp.x = Eigen::Map<const Eigen::VectorXd>(x.data(), comp.x.size());
    scatter(static_cast<int>(c), comp.x, u_[c]);
    restore(cp, fmt::format("{}flux_{}", prefix, c), phi_[c]);
  }
  restore(cp, prefix + "pressure", p_);
  restore(cp, prefix + "void_fraction", eps_);
  restore(cp, prefix + "void_fraction_rate", deps_dt_);
  restore(cp, prefix + "implicit_coefficient", ksl_);
  if (cp.has(prefix + "viscosity_factor")) {
    restore(cp, prefix + "viscosity_factor", visc_);
    variable_viscosity_ = true;
  }
  restore(cp, prefix + "particle_velocity", us_);
  restore(cp, prefix + "explicit_force", force_);
  const std::vector<double>& scalars = sized(cp, prefix + "scalars", 2);
  time_s_ = scalars[0];
  drive_gradient_ = scalars[1];
  const std::vector<std::int64_t>& steps = cp.integers(prefix + "steps");
  if (steps.size() != 1) throw hs::common::ConfigError("checkpoint: \"" + prefix + "steps\" must hold one value");
  steps_ = steps[0];
  if (cp.has(prefix + "pressure_amg_state")) {   // absent from checkpoints written before 2026-12-07: fresh hierarchy
    const std::vector<std::int64_t>& amg = cp.integers(prefix + "pressure_amg_state");
    if (amg.size() != 6) {
      throw hs::common::ConfigError("checkpoint: \"" + prefix + "pressure_amg_state\" must hold 6 values");
    }
    pressure_.restore(AmgCheckpoint{.built = amg[0] != 0,
                                    .setup_values = cp.doubles(prefix + "pressure_amg_setup_matrix"),
                                    .fresh_iterations = amg[1], .fresh = amg[2] != 0, .stale = amg[3] != 0,
                                    .setups = amg[4], .reuses = amg[5]});
  }
  coefficients_dirty_ = true;
  if (variable_viscosity_) fill_cell_ghosts(visc_);
  update_viscous_force();   // derived from the restored velocity and viscosity: a resumed run samples the same stress
}

}  // namespace hs::unresolved
