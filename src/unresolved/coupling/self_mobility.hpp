// SPDX-License-Identifier: MIT
// The grid's self-mobility: the fluid velocity a sphere's own force induces at its centre, per newton.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// The tube a table is measured in: axis direction (0, 1, 2) through axis_point_m, radius.
struct TubeFrame {
  int axis = 2;
  hs::common::Vec3 axis_point_m{};
  double radius_m = 0.0;
};

/// Why: in two-way coupling a sphere gives its force to the cells it covers, and the velocity the drag law then
/// interpolates at its centre contains the sphere's own disturbance, whereas the drag law (and every closure fitted
/// on resolved runs) wants the undisturbed velocity (Horwitz & Mani 2016, J Comput Phys 318:85). For a sphere
/// larger than a cell the disturbance exceeds the sphere's own velocity (a force spread over the sphere's volume
/// moves its centre at 1.5 times the Stokes velocity), so no per-step closed form applies; instead the coupling
/// subtracts M F, with F the force the sphere gave the fluid in the last step and M this measured response.
/// Without smoothing the correction is for spheres smaller than a cell (point particles), where it works (sphere
/// pulled along a tube, sphere_in_tube_drag_test, beta = 3 pi mu d_p): d_p / dx = 0.56, beta M = 0.1-0.5, drag law
/// within 1.1%; d_p / dx = 0.94, beta M = 1.7 on the axis, over-corrected by 13%; d_p / dx = 1.9, where the sphere's
/// own void fraction dominates its cells (beta M = 1.2-4.6), the sphere and the fluid it drags run away together.
/// With the exchange smoothed over a length l (diffusion_smoothing.hpp) the force reaches the fluid over l, not over
/// the cells the markers fall in, M is measured with the same smoothing, and it no longer depends on d_p / dx but
/// on l / d_p (continuum limit M = 1 / (6 pi mu l) for a point force smoothed by the kernel exp(-r/l) / (4 pi l^2 r)
/// in unbounded fluid): the coupling then allows any grid and refuses only a beta M that the lagged correction cannot
/// follow (CfdDemCoupling::self_mobility).
///
/// M is measured once on the run's own grid, drive and marker map (DividedMap): for a sphere at a few radial
/// stations from the axis to R - d/2, a force along the axis, along the radius and along the azimuth is spread over
/// its 29 markers in a fluid at rest, the flow is run to steady state (Stokes: the disturbance's Reynolds number is
/// ~1e-4), and the velocity interpolated at the centre gives the diagonal of M in the tube frame (the azimuthal
/// couplings vanish by the mirror symmetry through the sphere's radial plane, the axial-radial ones by the one
/// through its cross-section, which the grid keeps at a cell centre, where the stations sit). The measurement
/// includes the tube-wide response of the run's drive (with a pressure-gradient drive an axial force also adds a
/// Poiseuille flow, ~7% of the Stokes mobility at D = 30 um, L = 60 um). Between stations M is interpolated
/// linearly. M varies by up to +-30% with where the sphere sits in a cell (markers and interpolation change cells;
/// the stations fall at different such positions, hence the table's zig-zag): the correction is as good as that.
class SelfMobility {
 public:
  /// Measures the table; `drive` gives the mode of the run's flow drive (its target value is set to zero: the
  /// response is linear), `fluid` the run's plasma. eps_min > 0: the sphere's own void fraction (clipped there) is
  /// in the fluid, as in a run with void-fraction feedback; 0: eps = 1. smoothing_length_m > 0: the force and the
  /// solid fraction are smoothed over that length, as the coupling smooths them.
  SelfMobility(const FvmGrid& grid, const FluidProperties& fluid, const FlowDrive& drive, const TubeFrame& frame,
               double sphere_diameter_m, double eps_min, double smoothing_length_m = 0.0, int stations = 8);

  /// Velocity the force F (N, on the fluid) of a sphere at x induces at x itself, m/s.
  [[nodiscard]] hs::common::Vec3 induced_velocity(const hs::common::Vec3& x_m, const hs::common::Vec3& force_N) const;

  /// Diagonal of M at x (axial, radial, azimuthal), m/s per N.
  [[nodiscard]] hs::common::Vec3 mobility_at(const hs::common::Vec3& x_m) const;
  [[nodiscard]] double sphere_diameter_m() const { return diameter_m_; }
  [[nodiscard]] const std::vector<double>& station_radii_m() const { return rho_; }
  /// Diagonal of M at each station, m/s per N: axial, radial, azimuthal.
  [[nodiscard]] const std::vector<hs::common::Vec3>& mobility_m_s_N() const { return m_; }

 private:
  [[nodiscard]] hs::common::Vec3 at(double rho_m) const;

  TubeFrame frame_;
  double diameter_m_;
  std::vector<double> rho_;
  std::vector<hs::common::Vec3> m_;
};

}  // namespace hs::unresolved
