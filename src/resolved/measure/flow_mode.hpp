// SPDX-License-Identifier: MIT
// Classifies the motion of a cell in shear: tumbling, tank-treading, steady or intermediate, from the
// inclination of its long axis and the phase of one marker vertex around the centroid.
#pragma once

#include <span>
#include <string>

namespace hs::resolved {

enum class FlowMode { steady, tank_treading, tumbling, intermediate };

std::string to_string(FlowMode mode);

/// `inclination_rad`: long-axis angle in the shear plane, folded to (-pi/2, pi/2] (see inclination_angle);
/// `marker_phase_rad`: angle of a marker vertex about the centroid in the shear plane, in (-pi, pi].
/// Rules (heuristics, stated so a reader can check them):
///  - tumbling: the unwrapped inclination turns by more than pi (the whole body rotates);
///  - tank-treading: inclination range below `swing_limit_rad` while the marker turns by more than 2 pi;
///  - steady: inclination range below `swing_limit_rad` and the marker turns by less than pi/2;
///  - intermediate: anything else (swinging, rolling, mixed).
FlowMode classify_flow_mode(std::span<const double> inclination_rad, std::span<const double> marker_phase_rad,
                            double swing_limit_rad = 0.35);

/// Where a disc's normal points, from the mean of its angle to the local vorticity (normal_to_vorticity_angle) over a
/// window: "rolling" below 30 deg (the disc spins in the shear plane: the inclination of its long axis then turns like
/// a tumbling body's), "in-shear-plane" above 60 deg (tumbling, swinging, tank-treading), "oblique" between (kayaking);
/// "" for a NaN mean (nothing sampled). The thresholds split the quarter circle in three equal parts: a convention,
/// stated so it can be checked.
std::string classify_disc_orientation(double mean_normal_to_vorticity_rad);

/// RBC aspect ratio (thickness over diameter) as a spheroid, r_e ~ 0.37: the value the campaign uses for Jeffery periods.
inline constexpr double kRbcAspectRatio = 0.37;

/// Jeffery (1922) period of a rigid spheroid of aspect ratio r_e in simple shear: T = 2 pi (r_e + 1/r_e) / gamma_dot
/// (one full turn of the body; its shape repeats every T/2). 19.3 / gamma_dot at r_e = 0.37.
double jeffery_period(double shear_rate_1_s, double aspect_ratio = kRbcAspectRatio);

/// Removes jumps larger than half of `modulus` between consecutive samples (angle unwrapping).
void unwrap(std::span<double> angles, double modulus);

}  // namespace hs::resolved
