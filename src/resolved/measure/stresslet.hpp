// SPDX-License-Identifier: MIT
// A cell's stresslet from the forces on its membrane, and its share of a sheared suspension's stress.
#pragma once

#include <array>
#include <span>

#include "common/vec3.hpp"

namespace hs::resolved {

/// Symmetric, traceless 3x3 tensor in N m.
using Stresslet = std::array<std::array<double, 3>, 3>;

/// The stresslet (Batchelor 1970, J Fluid Mech 41:545) of a closed membrane from the force the fluid exerts on
/// it at each vertex (N; for a discretised traction t, t_k A_k): S = sym(sum_k (x_k - x_c) (x) f_k) minus its
/// trace part, with x_c the vertices' centroid. For a rigid sphere of radius a in a strain E, S = 20/3 pi mu a^3 E.
/// pre: vertices unwrapped across periodic boundaries, one force per vertex.
[[nodiscard]] Stresslet stresslet(std::span<const common::Vec3> vertices_m, std::span<const common::Vec3> fluid_force_N);

/// The cell's intrinsic viscosity in simple shear u_flow = gamma_dot x_gradient: [eta] = S_fg / (mu gamma_dot V),
/// so that a dilute suspension at volume fraction phi has eta_r = 1 + [eta] phi. Einstein's 2.5 for a rigid sphere.
[[nodiscard]] double intrinsic_viscosity(const Stresslet& s, double viscosity_Pa_s, double shear_rate_per_s,
                                         double cell_volume_m3, int flow_axis, int gradient_axis);

}  // namespace hs::resolved
