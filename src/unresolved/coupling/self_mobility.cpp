// SPDX-License-Identifier: MIT
// The self-mobility table: steady responses of the run's grid to one sphere's force at radial stations.
#include "unresolved/coupling/self_mobility.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/coupling/diffusion_smoothing.hpp"
#include "unresolved/coupling/divided_void_fraction.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

constexpr double kMaxViscousNumber = 4.0;

Vec3 unit(int axis) {
  Vec3 e{};
  e[axis] = 1.0;
  return e;
}

/// Steady velocity at x (m/s) when a sphere of diameter d at x gives the fluid at rest the force F (N) through its
/// 29 markers, as CfdDemCoupling::exchange_drag spreads the drag (then smoothed as the run smooths it, if it does).
Vec3 steady_response(const FvmGrid& grid, const FluidProperties& fluid, const FlowDrive& drive, double length_scale_m,
                     const Vec3& x, double diameter_m, double eps_min, DiffusionSmoothing* smoothing,
                     const Vec3& force_N) {
  // Implicit Euler with dt = R^2 / nu damps the slowest (tube) mode ~7x per step; the steady state of the linear
  // problem does not depend on dt. But the PISO steps stop converging at large viscous numbers nu dt / dx^2 (15 cells
  // across D = 30 um, sphere on the axis: at 56 and 25 the response grows ~2x every 10 steps, at 10 it settles in ~50
  // steps, at 4 in ~20; 10 cells across settle at 25), so dt is capped at viscous number 4.
  const double nu = fluid.kinematic_viscosity_m2_s;
  const double dt = std::min(length_scale_m * length_scale_m / nu, kMaxViscousNumber * grid.dx_m() * grid.dx_m() / nu);
  FvmSolver solver(grid, fluid, {.dt_s = dt, .max_courant = 1e30, .pressure = {.tolerance = 1e-12, .rel_tol = 0.0},
                                 .momentum_tolerance = 1e-12},
                   drive, MPI_COMM_SELF);
  ParticleStore sphere;
  sphere.add({.position_m = x, .velocity_m_s = {}, .angular_velocity_rad_s = {}, .radius_m = 0.5 * diameter_m, .mass_kg = 1.0, .id = 0});
  DividedMap map(grid);
  map.locate(sphere);
  if (eps_min > 0.0) {   // the run's void-fraction feedback: the sphere's own eps roughly doubles M at d_p / dx ~ 2
    BlockField<double>& eps = solver.void_fraction();
    (void)map.void_fraction(sphere, eps_min, eps, smoothing);   // as CfdDemCoupling::fill_fields
    solver.coupling_fields_changed();
  }
  BlockField<Vec3>& f = solver.explicit_force_density_N_m3();
  for (int m = 0; m < kMarkersPerSphere; ++m) {
    const std::size_t c = map.cell(0, m);
    f[c] += force_N / (kMarkersPerSphere * map.fluid_volume_m3(c));
  }
  if (smoothing != nullptr) smoothing->smooth(f);
  fill_cell_field_ghosts(grid, f);
  Vec3 u{};
  for (int step = 0; step < 200; ++step) {
    solver.step();
    const Vec3 next = solver.velocity_at(x);
    const bool settled = step >= 4 && norm(next - u) <= 1e-8 * norm(next);
    u = next;
    if (settled) return u;
  }
  throw hs::common::NumericalError(fmt::format("self-mobility: the response at ({:.4g}, {:.4g}, {:.4g}) m did not settle in 200 steps",
                                               x[0], x[1], x[2]));
}

}  // namespace

SelfMobility::SelfMobility(const FvmGrid& grid, const FluidProperties& fluid, const FlowDrive& drive, const TubeFrame& frame,
                           double sphere_diameter_m, double eps_min, double smoothing_length_m, int stations)
    : frame_(frame), diameter_m_(sphere_diameter_m) {
  const double reach = frame.radius_m - 0.5 * sphere_diameter_m;
  if (!(reach > 0.0) || stations < 2) {
    throw hs::common::ConfigError(fmt::format("self-mobility: a sphere of {:.4g} m does not fit a tube of radius {:.4g} m "
                                              "(or fewer than 2 stations)", sphere_diameter_m, frame.radius_m));
  }
  FlowDrive rest = drive;   // the response is linear: the drive's target is zero
  rest.pressure_gradient_Pa_m = 0.0;
  rest.flow_rate_m3_s = 0.0;
  const int ray = frame.axis == 0 ? 1 : 0;                 // stations along this grid axis
  const int azimuth = 3 - frame.axis - ray;
  // Axially at the cell centre nearest the middle of the box (M varies up to +-30% with the position in a cell).
  const double dx = grid.dx_m();
  const double lo = grid.origin_m()[frame.axis];
  const int n_axial = grid.cells()[static_cast<std::size_t>(frame.axis)];
  const double along = lo + (std::floor(0.5 * n_axial) + 0.5) * dx;
  std::unique_ptr<DiffusionSmoothing> smoothing;
  if (smoothing_length_m > 0.0) smoothing = std::make_unique<DiffusionSmoothing>(grid, smoothing_length_m);
  const double force = 1e-12;   // N: Reynolds number of the disturbance ~1e-4 in plasma at dx ~ 3 um
  for (int k = 0; k < stations; ++k) {
    const double rho = reach * k / (stations - 1);
    Vec3 x = frame.axis_point_m;
    x[frame.axis] = along;
    x[ray] += rho;
    Vec3 m{};
    const std::array<int, 3> dirs{frame.axis, ray, azimuth};
    for (std::size_t d = 0; d < 3; ++d) {
      const Vec3 e = unit(dirs[d]);
      m[static_cast<int>(d)] = dot(steady_response(grid, fluid, rest, frame.radius_m, x, sphere_diameter_m, eps_min,
                                             smoothing.get(), force * e), e) / force;
    }
    rho_.push_back(rho);
    m_.push_back(m);
  }
}

Vec3 SelfMobility::mobility_at(const Vec3& x_m) const {
  Vec3 r = x_m - frame_.axis_point_m;
  r[frame_.axis] = 0.0;
  return at(norm(r));
}

Vec3 SelfMobility::at(double rho_m) const {
  if (rho_m >= rho_.back()) return m_.back();
  const double s = rho_m / rho_.back() * static_cast<double>(rho_.size() - 1);
  const auto k = static_cast<std::size_t>(s);
  const double w = s - static_cast<double>(k);
  return (1.0 - w) * m_[k] + w * m_[k + 1];
}

Vec3 SelfMobility::induced_velocity(const Vec3& x_m, const Vec3& force_N) const {
  Vec3 r = x_m - frame_.axis_point_m;
  r[frame_.axis] = 0.0;
  const double rho = norm(r);
  const Vec3 m = at(rho);
  const Vec3 axial = force_N[frame_.axis] * unit(frame_.axis);
  const Vec3 transverse = force_N - axial;
  if (rho <= 1e-9 * frame_.radius_m) return m[0] * axial + m[1] * transverse;   // on the axis radial = azimuthal
  const Vec3 er = r / rho;
  const Vec3 radial = dot(transverse, er) * er;
  return m[0] * axial + m[1] * radial + m[2] * (transverse - radial);
}

}  // namespace hs::unresolved
