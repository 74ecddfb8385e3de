// SPDX-License-Identifier: MIT
// ParaView frames of a CFD-DEM run: particles.pvd (vtk/particles_<step>.vtp) and fields.pvd (vtk/fields_<step>.vti).
#pragma once

#include <filesystem>
#include <memory>

#include "common/io/vtk_polydata.hpp"
#include "unresolved/cases/cfd_dem_case.hpp"

namespace hs::unresolved {

/// Writes a frame every `every_s` of simulated time (0: only the final one). Files are named by CFD step, so a
/// resumed run continues the series (PvdSeries reloads its entries) and never overwrites an older frame.
/// Only reads the solvers: the run's results do not depend on whether frames are written.
/// On z-slabs every rank calls after_step() (collective): rank 0 of the solvers' communicator gathers the slabs'
/// cells and particles and writes one file per frame, the file one rank writes (particles in id order either way).
class CfdDemFrames {
 public:
  /// `folder` is used on rank 0 only (others may pass it empty).
  CfdDemFrames(const std::filesystem::path& folder, double every_s);
  /// Call after every CFD step; `final_step` forces a frame.
  void after_step(const CfdDemSolvers& run, long step, bool final_step);

 private:
  void write(const CfdDemSolvers& run, long step);

  std::filesystem::path folder_;
  double every_s_;
  std::unique_ptr<hs::common::PvdSeries> particles_pvd_, fields_pvd_;
};

}  // namespace hs::unresolved
