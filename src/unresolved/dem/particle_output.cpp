// SPDX-License-Identifier: MIT
// VTK output of the particles.
#include "unresolved/dem/particle_output.hpp"

#include <cstdint>
#include <vector>

#include "common/io/vtk_polydata.hpp"

namespace hs::unresolved {
namespace {

std::vector<hs::common::Vec3> owned_vectors(const ParticleStore::Vec3Columns& c, std::size_t n) {
  std::vector<hs::common::Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = {c[0][i], c[1][i], c[2][i]};
  return out;
}

}  // namespace

void write_particles_vtp(const ParticleStore& p, const std::filesystem::path& file) {
  const std::size_t n = p.n_owned();
  const auto points = owned_vectors(p.position_m(), n);
  hs::common::VtkPolyData vtp(points);
  std::vector<double> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<double>(p.id()[i]);
  vtp.add_point_scalar("id", ids);
  vtp.add_point_scalar("radius_m", std::span<const double>(p.radius_m().data(), n));
  vtp.add_point_vector("velocity_m_s", owned_vectors(p.velocity_m_s(), n));
  vtp.add_point_vector("angular_velocity_rad_s", owned_vectors(p.angular_velocity_rad_s(), n));
  vtp.add_point_vector("force_N", owned_vectors(p.force_N(), n));
  vtp.add_point_vector("external_force_N", owned_vectors(p.external_force_N(), n));
  // The coupling's drag beta (u_f - v) at the particle and its lift, where the run has them.
  if (p.drag_used() && p.drag_coefficient_N_s_m().size() >= n && p.fluid_velocity_m_s()[0].size() >= n) {
    std::vector<hs::common::Vec3> drag(n);
    const auto& u = p.fluid_velocity_m_s();
    const auto& v = p.velocity_m_s();
    for (std::size_t i = 0; i < n; ++i) {
      const double b = p.drag_coefficient_N_s_m()[i];
      drag[i] = {b * (u[0][i] - v[0][i]), b * (u[1][i] - v[1][i]), b * (u[2][i] - v[2][i])};
    }
    vtp.add_point_vector("drag_force_N", drag);
  }
  if (p.lift_force_N()[0].size() >= n) vtp.add_point_vector("lift_force_N", owned_vectors(p.lift_force_N(), n));
  vtp.add_point_scalar("deformation_index", std::span<const double>(p.deformation_index().data(), n));
  vtp.add_point_scalar("inlet_opening", std::span<const std::int32_t>(p.inlet_opening().data(), n));
  vtp.write(file);
}

}  // namespace hs::unresolved
