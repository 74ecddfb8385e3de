// SPDX-License-Identifier: MIT
// The CFD-DEM solvers of a case with every solve at 1e-12, for the tests that compare a run on slabs with one rank's.
#pragma once

#include "unresolved/cases/cfd_dem_case.hpp"

namespace hs::test {

/// The AMG preconditioner differs with the rank count, so runs agree to cond x tolerance: at 1e-12 round-off bounds
/// that (the production 1e-6 would be the band instead).
inline hs::unresolved::CfdDemSetup tight_solves(hs::unresolved::CfdDemSetup s) {
  s.piso.pressure = {.tolerance = 1e-12, .rel_tol = 0.0, .max_iterations = 1000};
  s.piso.momentum_tolerance = 1e-12;
  return s;
}

}  // namespace hs::test
