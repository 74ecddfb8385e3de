// SPDX-License-Identifier: MIT
// The cytoplasm's viscosity of the single-RBC cases: [cell] cytoplasm_viscosity_Pa_s and its checks.
#pragma once

#include "common/config/config_file.hpp"
#include "resolved/cases/cell_numerics.hpp"

namespace hs::resolved {

/// Dynamic viscosity of the cytoplasm (haemoglobin solution) of healthy red cells, ~6 mPa s at 37 C: Cokelet &
/// Meiselman 1968, Science 162:275 (the value as the resolved-cell literature cites it; the paper itself was not read
/// here). Against plasma's ~1.2 mPa s this is the viscosity ratio ~5 the literature uses.
inline constexpr double kHealthyCytoplasmViscosity_Pa_s = 6.0e-3;

/// Reads [cell] cytoplasm_viscosity_Pa_s (Pa s, 1e-5..1) and returns the ratio to the plasma's dynamic viscosity.
/// Absent: kHealthyCytoplasmViscosity_Pa_s (ratio 5.85 against the shipped 1.025 mPa s plasma). A ratio within 1e-12
/// of 1 is 1 exactly, so the lattice keeps one phase (the runs before #27, bit for bit). Records the ratio as the
/// derived key viscosity_ratio.
[[nodiscard]] double read_cytoplasm_viscosity_ratio(hs::common::ConfigSection cell, double plasma_viscosity_Pa_s);

/// After derive_cell_numerics(): refuses (ConfigError naming [cell] cytoplasm_viscosity_Pa_s) a ratio that puts the
/// tau of either phase below 0.55 (the wall closure is amplified by 1 / (tau - 1/2), tested down to 0.6). The top is
/// bounded by [numerics] max_tau, which derive_cell_numerics applies to the cytoplasm's tau.
void check_cytoplasm_relaxation(hs::common::ConfigSection cell, const CellNumerics& numerics);

}  // namespace hs::resolved
