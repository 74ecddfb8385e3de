// SPDX-License-Identifier: MIT
// A sparse matrix's rows on this rank, in the compressed-row form hypre's IJ interface takes.
#pragma once

#include <vector>

namespace hs::unresolved {

/// This rank's rows of a sparse matrix in CSR form. The rows are distributed in rank order: rank k owns the global
/// rows first_row .. first_row + rows - 1, right after rank k-1's (hypre's IJ layout), and the column indices are
/// global. On one rank first_row is 0 and the matrix is the whole one.
struct CsrMatrix {
  int rows = 0;
  int first_row = 0;
  std::vector<int> row_ptr;     // size rows + 1
  std::vector<int> cols;        // global column indices
  std::vector<double> values;
};

}  // namespace hs::unresolved
