// SPDX-License-Identifier: MIT
// `hemoscale validate pries`: the Fahraeus-Lindqvist table of the CFD-DEM tube against Pries et al. 1992.
#pragma once

#include "common/case_request.hpp"

namespace hs::unresolved {

/// D = 30, 50, 100 um x Ht_c = 0.05, 0.10, 0.15; writes X.json/.csv/.png for --json X.json, else
/// pries_validation.json/.csv/.png in the working directory. --closures NAME|FILE|DIR picks the drag (a name or a drag closure file) or, for a
/// folder, the learned set DIR/{drag_coefficient,lift_coefficient,deformation_index}/*.toml. Returns 0 when
/// every case ran (the errors are reported, not judged: the rigid-sphere baseline is not expected to pass).
int validate_pries(const hs::common::TaskOptions& options);
/// The same table with the Haberman-Sayre confinement factor on the drag ([coupling] wall_correction); without --json
/// written as pries_wall_validation.json/.csv/.png.
int validate_pries_wall(const hs::common::TaskOptions& options);
/// The same table with the factor relative to the learned closures' own tube, K(d_p / D) / K(d_p / 50 um)
/// (haberman_sayre_relative: they were fitted in that tube, so they already hold its confinement).
int validate_pries_wall_relative(const hs::common::TaskOptions& options);

}  // namespace hs::unresolved
