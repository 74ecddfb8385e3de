// SPDX-License-Identifier: MIT
// Confinement (wall) correction of the drag on a sphere in a circular tube: Haberman & Sayre (1958).
#pragma once

#include <string>
#include <string_view>

namespace hs::closures {

/// Which confinement factor K multiplies a drag closure's beta_p = 3 pi mu d_p correction (so F = K F_unbounded).
///   none:           K = 1 (the closures describe an unbounded sphere; right for boxes and wide tubes).
///   haberman_sayre: K(lambda = d_p / D) of a sphere translating on the axis of a long tube through fluid at rest
///                   at infinity (Haberman & Sayre 1958, David Taylor Model Basin Rep. 1143; Happel & Brenner,
///                   Low Reynolds number hydrodynamics, 1965, sec. 7-4). Every particle gets the on-axis value: the
///                   off-axis factor is larger (it diverges at contact with the wall), so this is a lower bound away
///                   from the axis; at RBC confinement (lambda 0.056-0.19 for D = 100-30 um) K = 1.13-1.62.
///   haberman_sayre_relative: K(d_p / D) / K(d_p / D_fit) for closures fitted in a tube of diameter D_fit (the learned
///                   ones: the campaign's 50 um tube), which already hold that tube's confinement. The resolved runs
///                   at D = 30 um gave C_d Re_p 1.20-1.27x the 50 um tube's at the same r* and Re; this ratio is 1.24
///                   (docs/cfd-dem.md).
enum class WallCorrection { none, haberman_sayre, haberman_sayre_relative };

/// The tube the learned closures were fitted in: cases/campaign/tube-re-rstar (R_c = 25 um; data/resolved/README.md).
inline constexpr double kLearnedClosureTubeDiameter_m = 50e-6;

/// Largest lambda accepted: up to 0.6 the Haberman-Sayre formula agrees with Bohlin's (1960) series within 4.2%
/// (data/reference/sphere_in_tube_wall_correction.csv); beyond, the two diverge and lubrication takes over.
inline constexpr double kMaxConfinementLambda = 0.6;

/// Haberman-Sayre K(lambda) = (1 - 0.75857 l^5) / (1 - 2.1050 l + 2.0865 l^3 - 1.7068 l^5 + 0.72603 l^6)
/// (shared/reference/validation/README.md). Throws ConfigError for lambda outside [0, kMaxConfinementLambda].
[[nodiscard]] double haberman_sayre_factor(double lambda);

/// "none", "haberman_sayre" or "haberman_sayre_relative"; anything else is a ConfigError naming the allowed values.
[[nodiscard]] WallCorrection wall_correction_from_name(std::string_view name);
[[nodiscard]] std::string wall_correction_name(WallCorrection w);

/// K for a sphere of diameter d_p in a tube of diameter D under correction `w` (1 for none; relative to the learned
/// closures' tube for haberman_sayre_relative).
[[nodiscard]] double wall_correction_factor(WallCorrection w, double particle_diameter_m, double tube_diameter_m);

}  // namespace hs::closures
