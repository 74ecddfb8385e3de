// SPDX-License-Identifier: MIT
// FvmGrid: boundary conditions per named opening (which face nodes an opening holds, its profile and flow rate).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/fvm/fvm_grid.hpp"

namespace hs::unresolved {
namespace {

using hs::common::OpeningCondition;
using hs::common::OpeningFlowType;
using hs::common::Vec3;

/// The box side an opening lies on: the axis of its normal (check_openings made it a face's outward normal).
std::array<int, 2> face_of(const hs::common::Opening& o) {
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (std::abs(o.normal[a]) > std::abs(o.normal[axis])) axis = a;
  }
  return {axis, o.normal[axis] > 0.0 ? 1 : 0};
}

std::string side_name(int axis, int high) { return fmt::format("{}{}", "xyz"[axis], high == 1 ? '+' : '-'); }

const char* side_type_name(SideType t) {
  switch (t) {
    case SideType::periodic: return "periodic";
    case SideType::wall: return "wall";
    case SideType::velocity_inlet: return "velocity_inlet";
    case SideType::pressure_outlet: return "pressure_outlet";
  }
  return "?";
}

}  // namespace

void FvmGrid::set_up_openings() {
  if (spec_.openings.empty()) return;
  hs::common::check_opening_conditions(spec_.openings, shape_, spec_.box_m);
  for (const OpeningCondition& oc : spec_.openings) {
    const auto [axis, high] = face_of(oc.opening);
    const SideCondition& s = side(axis, high);
    if (s.type != SideType::wall) {
      throw hs::common::ConfigError(fmt::format(
          "FVM grid: opening '{}' lies on the {} side of the box, whose condition is {}; a side with openings must "
          "be a wall (the openings are its inlets and outlets, the rest of it is wall)",
          oc.opening.name, side_name(axis, high), side_type_name(s.type)));
    }
    opening_nodes_.push_back({.axis = axis, .high = high, .nodes = {}});
  }
}

const OpeningCondition* FvmGrid::opening_at(int axis, int high, const Vec3& x_m) const {
  for (std::size_t k = 0; k < spec_.openings.size(); ++k) {
    const OpeningNodes& on = opening_nodes_[k];
    if (on.axis != axis || on.high != high) continue;
    const hs::common::Opening& o = spec_.openings[k].opening;
    if (o.lateral_m(x_m) <= o.radius_m) return &spec_.openings[k];
  }
  return nullptr;
}

bool FvmGrid::classify_opening_node(int c, std::array<int, 3> ijk, const Vec3& p) {
  const int high = ijk[static_cast<std::size_t>(c)] == 0 ? 0 : 1;
  const OpeningCondition* oc = opening_at(c, high, p);
  if (oc == nullptr) return false;
  auto& kind = kind_[static_cast<std::size_t>(c)];
  auto& fixed = fixed_[static_cast<std::size_t>(c)];
  const std::size_t idx = kind.index(ijk[0], ijk[1], ijk[2]);
  opening_nodes_[static_cast<std::size_t>(oc - spec_.openings.data())].nodes.push_back(idx);
  if (oc->type == OpeningFlowType::pressure_outlet) {
    kind[idx] = static_cast<std::uint8_t>(NodeKind::active);
    return true;
  }
  // The developed profile's shape, signed along +c; finish_openings() scales it to the flow rate.
  const double r = oc->opening.lateral_m(p) / oc->opening.radius_m;
  const double into = oc->type == OpeningFlowType::flow_rate_inlet ? -1.0 : 1.0;
  kind[idx] = static_cast<std::uint8_t>(NodeKind::fixed);
  fixed[idx] = into * oc->opening.normal[c] * std::max(0.0, 1.0 - r * r);
  return true;
}

/// Scales each prescribed profile so that its discrete flux sum(aperture dx^2 |u_n|) is the flow rate asked for,
/// and checks that every opening holds at least one face node.
void FvmGrid::finish_openings() {
  double inflow_m3_s = 0.0;
  for (const OpeningCondition& oc : spec_.openings) {
    if (oc.type == OpeningFlowType::flow_rate_inlet) inflow_m3_s += oc.flow_rate_m3_s;
  }
  // On slabs an opening's nodes may lie on several blocks: its node count and flux are summed over all of them.
  const auto global_sum = [&](double local) {
    double all = local;
    if (slabs_ != nullptr) MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_SUM, slabs_->comm());
    return all;
  };
  for (std::size_t k = 0; k < spec_.openings.size(); ++k) {
    const OpeningCondition& oc = spec_.openings[k];
    const OpeningNodes& on = opening_nodes_[k];
    if (global_sum(static_cast<double>(on.nodes.size())) == 0.0) {
      throw hs::common::ConfigError(fmt::format(
          "FVM grid: opening '{}' (radius_m = {:.6g}) holds no face node of the grid (dx_m = {:.6g}): a face centre "
          "belongs to an opening when it lies in the fluid within the disc; give the disc a radius of a cell or more",
          oc.opening.name, oc.opening.radius_m, dx_m_));
    }
    if (oc.type == OpeningFlowType::pressure_outlet) continue;
    auto& fixed = fixed_[static_cast<std::size_t>(on.axis)];
    const auto& ap = aperture_[static_cast<std::size_t>(on.axis)];
    double local_flux = 0.0;
    for (const std::size_t idx : on.nodes) local_flux += ap[idx] * dx_m_ * dx_m_ * std::abs(fixed[idx]);
    const double flux = global_sum(local_flux);
    if (!(flux > 0.0)) {
      throw hs::common::ConfigError(fmt::format(
          "FVM grid: opening '{}' has no open face inside its disc at dx_m = {:.6g} (every face node sits on its rim); "
          "refine the grid or widen the disc", oc.opening.name, dx_m_));
    }
    const double target =
        oc.type == OpeningFlowType::flow_rate_inlet ? oc.flow_rate_m3_s : oc.flow_fraction * inflow_m3_s;
    for (const std::size_t idx : on.nodes) fixed[idx] *= target / flux;
  }
  for (int c = 0; c < 3; ++c) fill_ghosts(fixed_[static_cast<std::size_t>(c)]);
}

}  // namespace hs::unresolved
