// SPDX-License-Identifier: MIT
// The fluid's volume flux through an opening on a side of the FVM box, as the solver's own face fluxes count it.
#pragma once

#include "common/geometry/opening.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// Sum over the box faces inside the opening's disc (lateral <= radius + dx) of eps_f a h^2 u, eps_f the mean of
/// the two cells beside the face (ghost layer: zero gradient), a the face's aperture: the flux the pressure equation
/// balances. Positive along the opening's outward normal (out of the domain). On slabs collective: the whole
/// opening's flux on every rank. pre: the opening lies on a box side (check_openings).
[[nodiscard]] double opening_outward_flux_m3_s(const FvmSolver& fluid, const hs::common::Opening& opening);

}  // namespace hs::unresolved
