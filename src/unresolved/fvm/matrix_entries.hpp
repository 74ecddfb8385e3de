// SPDX-License-Identifier: MIT
// Write access to a distributed matrix's values where the solver keeps them, for assembly loops that fill in place.
#pragma once

namespace hs::unresolved {

/// The values of this rank's rows as hypre stores them: a block of the columns this rank owns, then a block of the
/// other ranks' columns. A position (from HypreMatrix or MomentumSolver::positions()) below own_count is in
/// the first. Filling these directly spares the momentum assembly a copy of every value every step.
struct MatrixEntries {
  double* own_columns = nullptr;
  double* other_columns = nullptr;
  int own_count = 0;

  [[nodiscard]] double& operator[](int position) const {
    return position < own_count ? own_columns[position] : other_columns[position - own_count];
  }
};

}  // namespace hs::unresolved
