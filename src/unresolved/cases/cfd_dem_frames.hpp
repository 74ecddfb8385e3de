// SPDX-License-Identifier: MIT
// ParaView frames of a CFD-DEM run: particles.pvd (vtk/particles_<step>.vtp) and fields.pvd (vtk/fields_<step>.vti).
#pragma once

#include <filesystem>
#include <memory>

#include "common/io/vtk_polydata.hpp"
#include "unresolved/dem/dem_system.hpp"
#include "unresolved/fvm/fvm_solver.hpp"

namespace hs::unresolved {

/// Writes a frame every `every_s` of simulated time (0: only the final one). Files are named by CFD step, so a
/// resumed run continues the series (PvdSeries reloads its entries) and never overwrites an older frame.
/// Only reads the solvers: the run's results do not depend on whether frames are written.
class CfdDemFrames {
 public:
  /// `folder` empty (ranks other than 0): writes nothing.
  CfdDemFrames(const std::filesystem::path& folder, double every_s);
  /// Call after every CFD step; `final_step` forces a frame.
  void after_step(const FvmSolver& fluid, const DemSystem& dem, long step, bool final_step);

 private:
  void write(const FvmSolver& fluid, const DemSystem& dem, long step);

  std::filesystem::path folder_;
  double every_s_;
  std::unique_ptr<hs::common::PvdSeries> particles_pvd_, fields_pvd_;
};

}  // namespace hs::unresolved
