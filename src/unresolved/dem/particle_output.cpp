// SPDX-License-Identifier: MIT
// VTK output of the particles.
#include "unresolved/dem/particle_output.hpp"

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
  vtp.add_point_scalar("deformation_index", std::span<const double>(p.deformation_index().data(), n));
  vtp.write(file);
}

}  // namespace hs::unresolved
