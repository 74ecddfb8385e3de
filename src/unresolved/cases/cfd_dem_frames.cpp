// SPDX-License-Identifier: MIT
// ParaView frames of a CFD-DEM run (particles .vtp, fluid cells .vti, each in a .pvd series).
#include "unresolved/cases/cfd_dem_frames.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/io/vtk_image.hpp"
#include "unresolved/dem/particle_output.hpp"

namespace hs::unresolved {

CfdDemFrames::CfdDemFrames(const std::filesystem::path& folder, double every_s) : folder_(folder), every_s_(every_s) {
  if (folder_.empty()) return;
  std::filesystem::create_directories(folder_ / "vtk");
  particles_pvd_ = std::make_unique<hs::common::PvdSeries>(folder_ / "particles.pvd");
  fields_pvd_ = std::make_unique<hs::common::PvdSeries>(folder_ / "fields.pvd");
}

void CfdDemFrames::after_step(const FvmSolver& fluid, const DemSystem& dem, long step, bool final_step) {
  if (folder_.empty()) return;
  // Due when the step crossed a multiple of every_s; stateless, so a resumed run keeps the same frame times.
  const auto slot = [&](double t_s) { return static_cast<long>(std::floor(t_s / every_s_ + 1e-9)); };
  const bool due = every_s_ > 0.0 && slot(fluid.time_s()) > slot(fluid.time_s() - fluid.settings().dt_s);
  if (!due && !final_step) return;
  write(fluid, dem, step);
}

void CfdDemFrames::write(const FvmSolver& fluid, const DemSystem& dem, long step) {
  const double t = fluid.time_s();
  const std::string pname = fmt::format("particles_{:07d}.vtp", step);
  write_particles_vtp(dem.particles(), folder_ / "vtk" / pname);
  particles_pvd_->add(t, "vtk/" + pname);
  // Cell centres as image points: velocity (cell mean of the faces), pressure (with the driving gradient),
  // void fraction eps and the local hematocrit 1 - eps.
  const FvmGrid& g = fluid.grid();
  const auto n = g.cells();
  const std::size_t cells = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]);
  std::vector<double> u, p, eps, ht;
  u.reserve(3 * cells);
  p.reserve(cells);
  eps.reserve(cells);
  ht.reserve(cells);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const hs::common::Vec3 v = fluid.cell_velocity(i, j, k);
        u.insert(u.end(), {v.x, v.y, v.z});
        p.push_back(fluid.cell_pressure_Pa(i, j, k));
        eps.push_back(fluid.void_fraction()(i, j, k));
        ht.push_back(1.0 - eps.back());
      }
    }
  }
  const double dx = g.dx_m();
  const hs::common::Vec3 o = g.origin_m();
  hs::common::VtkImage image(n, {o.x + 0.5 * dx, o.y + 0.5 * dx, o.z + 0.5 * dx}, dx);
  image.add_vector("velocity_m_s", u);
  image.add_scalar("pressure_Pa", p, true);
  image.add_scalar("void_fraction", eps);
  image.add_scalar("local_hematocrit", ht);
  const std::string fname = fmt::format("fields_{:07d}.vti", step);
  image.write(folder_ / "vtk" / fname);
  fields_pvd_->add(t, "vtk/" + fname);
}

}  // namespace hs::unresolved
