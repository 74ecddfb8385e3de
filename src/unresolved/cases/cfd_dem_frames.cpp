// SPDX-License-Identifier: MIT
// ParaView frames of a CFD-DEM run (particles .vtp, fluid cells .vti, each in a .pvd series), gathered from the
// slabs when the run is distributed.
#include "unresolved/cases/cfd_dem_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <mpi.h>

#include "common/io/vtk_image.hpp"
#include "unresolved/cases/slab_gather.hpp"
#include "unresolved/dem/particle_output.hpp"

namespace hs::unresolved {
namespace {

/// The owned particles of every rank on rank 0, in id order, so that a frame is the same file on any rank count.
ParticleStore particles_in_id_order(const ParticleStore& mine, MPI_Comm comm) {
  ParticleStore copy = mine;   // pack_owned() reads through ParticleStore's non-const column visitor
  const std::size_t width = copy.packed_size();
  std::vector<double> packed;
  packed.reserve(width * copy.n_owned());
  for (std::size_t i = 0; i < copy.n_owned(); ++i) copy.pack_owned(i, packed);
  const std::vector<double> all = gathered(packed, comm).values;
  ParticleStore out;
  for (std::size_t at = 0; at + width <= all.size(); at += width) out.add_packed(all.data() + at);
  if (mine.drag_used()) (void)out.drag_coefficient_N_s_m();   // the drag column is written where the run has one
  std::vector<std::size_t> order(out.n_owned());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return out.id()[a] < out.id()[b]; });
  out.permute_owned(order);
  return out;
}

}  // namespace

CfdDemFrames::CfdDemFrames(const std::filesystem::path& folder, double every_s) : folder_(folder), every_s_(every_s) {
  if (folder_.empty()) return;
  std::filesystem::create_directories(folder_ / "vtk");
  particles_pvd_ = std::make_unique<hs::common::PvdSeries>(folder_ / "particles.pvd");
  fields_pvd_ = std::make_unique<hs::common::PvdSeries>(folder_ / "fields.pvd");
}

void CfdDemFrames::after_step(const CfdDemSolvers& run, long step, bool final_step) {
  if (folder_.empty() && run.slabs() == nullptr) return;   // nothing to write and no one to gather with
  const FvmSolver& fluid = run.fluid();
  // Due when the step crossed a multiple of every_s; stateless, so a resumed run keeps the same frame times (and
  // every rank, on the same simulated time, agrees).
  const auto slot = [&](double t_s) { return static_cast<long>(std::floor(t_s / every_s_ + 1e-9)); };
  const bool due = every_s_ > 0.0 && slot(fluid.time_s()) > slot(fluid.time_s() - fluid.settings().dt_s);
  if (!due && !final_step) return;
  write(run, step);
}

void CfdDemFrames::write(const CfdDemSolvers& run, long step) {
  const MPI_Comm comm = run.comm();
  const bool root = rank_of(comm) == 0 && !folder_.empty();
  const FvmSolver& fluid = run.fluid();
  const double t = fluid.time_s();
  const ParticleStore particles = particles_in_id_order(run.dem().particles(), comm);
  if (root) {
    const std::string pname = fmt::format("particles_{:07d}.vtp", step);
    write_particles_vtp(particles, folder_ / "vtk" / pname);
    particles_pvd_->add(t, "vtk/" + pname);
  }
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
  u = whole_grid(u, g, 3, comm);
  p = whole_grid(p, g, 1, comm);
  eps = whole_grid(eps, g, 1, comm);
  ht = whole_grid(ht, g, 1, comm);
  if (!root) return;
  const double dx = g.dx_m();
  const hs::common::Vec3 o = g.box_m().lo;
  hs::common::VtkImage image(g.global_cells(), {o.x + 0.5 * dx, o.y + 0.5 * dx, o.z + 0.5 * dx}, dx);
  image.add_vector("velocity_m_s", u);
  image.add_scalar("pressure_Pa", p, true);
  image.add_scalar("void_fraction", eps);
  image.add_scalar("local_hematocrit", ht);
  const std::string fname = fmt::format("fields_{:07d}.vti", step);
  image.write(folder_ / "vtk" / fname);
  fields_pvd_->add(t, "vtk/" + fname);
}

}  // namespace hs::unresolved
