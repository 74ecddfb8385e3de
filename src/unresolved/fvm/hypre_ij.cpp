// SPDX-License-Identifier: MIT
// hypre IJ matrices and vectors, with in-place value updates.
#include "unresolved/fvm/hypre_ij.hpp"

#include <_hypre_parcsr_mv.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hs::unresolved {

void check_row_layout(MPI_Comm comm, const CsrMatrix& a, std::string_view who) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  long mine = a.rows;
  long before = 0;
  MPI_Exscan(&mine, &before, 1, MPI_LONG, MPI_SUM, comm);
  if (rank == 0) before = 0;   // MPI_Exscan leaves rank 0's result undefined
  int bad = (a.first_row != before || a.rows < 0 || a.row_ptr.size() != static_cast<std::size_t>(a.rows) + 1) ? 1 : 0;
  int worst = 0;
  MPI_Allreduce(&bad, &worst, 1, MPI_INT, MPI_MAX, comm);
  if (worst != 0) {
    throw std::logic_error(std::string(who) + ": rows not distributed in rank order (rank " + std::to_string(rank) +
                           " holds rows from " + std::to_string(a.first_row) + ", expected " + std::to_string(before) +
                           "; every rank must pass only its own rows)");
  }
}

HypreVector::HypreVector(MPI_Comm comm, int first_row, int rows) : rows_(rows) {
  HYPRE_IJVectorCreate(comm, first_row, first_row + rows - 1, &ij_);
  HYPRE_IJVectorSetObjectType(ij_, HYPRE_PARCSR);
  HYPRE_IJVectorInitialize(ij_);
  HYPRE_IJVectorAssemble(ij_);
}

HypreVector::~HypreVector() { HYPRE_IJVectorDestroy(ij_); }

HYPRE_ParVector HypreVector::par() const {
  void* object = nullptr;
  HYPRE_IJVectorGetObject(ij_, &object);
  return static_cast<HYPRE_ParVector>(object);
}

std::span<double> HypreVector::values() {
  return {hypre_VectorData(hypre_ParVectorLocalVector(par())), static_cast<std::size_t>(rows_)};
}

void HypreVector::assign(std::span<const double> v) { std::copy_n(v.begin(), rows_, values().begin()); }

void HypreVector::copy_to(std::span<double> v) const {
  const double* data = hypre_VectorData(hypre_ParVectorLocalVector(par()));
  std::copy_n(data, rows_, v.begin());
}

HypreMatrix::HypreMatrix(MPI_Comm comm, const CsrMatrix& a) : rows_(a.rows), first_row_(a.first_row) {
  const int n = a.rows;
  const int lo = a.first_row;
  long mine = n;
  MPI_Allreduce(&mine, &global_rows_, 1, MPI_LONG, MPI_SUM, comm);
  HYPRE_IJMatrixCreate(comm, lo, lo + n - 1, lo, lo + n - 1, &ij_);
  HYPRE_IJMatrixSetObjectType(ij_, HYPRE_PARCSR);
  std::vector<HYPRE_Int> sizes(static_cast<std::size_t>(n));
  std::vector<HYPRE_BigInt> rows(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) {
    sizes[static_cast<std::size_t>(r)] = a.row_ptr[static_cast<std::size_t>(r) + 1] - a.row_ptr[static_cast<std::size_t>(r)];
    rows[static_cast<std::size_t>(r)] = lo + r;
  }
  HYPRE_IJMatrixSetRowSizes(ij_, sizes.data());
  HYPRE_IJMatrixInitialize(ij_);
  std::vector<HYPRE_BigInt> cols(a.cols.begin(), a.cols.end());
  HYPRE_IJMatrixSetValues(ij_, n, sizes.data(), rows.data(), cols.data(), a.values.data());
  HYPRE_IJMatrixAssemble(ij_);
  position_ = entry_positions(a);
  if (position_.size() != a.values.size()) {   // not empty(): a rank may hold no rows (a slab all solid)
    throw std::logic_error("HypreMatrix: hypre did not keep every entry of the pattern in place");
  }
}

HypreMatrix::~HypreMatrix() { HYPRE_IJMatrixDestroy(ij_); }

HYPRE_ParCSRMatrix HypreMatrix::par() const {
  void* object = nullptr;
  HYPRE_IJMatrixGetObject(ij_, &object);
  return static_cast<HYPRE_ParCSRMatrix>(object);
}

MatrixEntries HypreMatrix::entries() const {
  hypre_ParCSRMatrix* par_csr = par();
  return {.own_columns = hypre_CSRMatrixData(hypre_ParCSRMatrixDiag(par_csr)),
          .other_columns = hypre_CSRMatrixData(hypre_ParCSRMatrixOffd(par_csr)),
          .own_count = hypre_CSRMatrixNumNonzeros(hypre_ParCSRMatrixDiag(par_csr))};
}

void HypreMatrix::update_values(std::span<const double> values) {
  const MatrixEntries to = entries();
  const std::size_t nnz = position_.size();
  for (std::size_t q = 0; q < nnz; ++q) to[position_[q]] = values[q];
}

std::vector<int> HypreMatrix::entry_positions(const CsrMatrix& a) const {
  hypre_ParCSRMatrix* par_csr = par();
  const hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(par_csr);
  const hypre_CSRMatrix* offd = hypre_ParCSRMatrixOffd(par_csr);
  const HYPRE_Int* di = hypre_CSRMatrixI(diag);
  const HYPRE_Int* dj = hypre_CSRMatrixJ(diag);
  const HYPRE_Int* oi = hypre_CSRMatrixI(offd);
  const HYPRE_Int* oj = hypre_CSRMatrixJ(offd);
  const HYPRE_BigInt* offd_global = hypre_ParCSRMatrixColMapOffd(par_csr);
  const HYPRE_Int diag_nnz = hypre_CSRMatrixNumNonzeros(diag);
  const bool has_offd = hypre_CSRMatrixNumNonzeros(offd) != 0;
  const auto first = static_cast<long>(hypre_ParCSRMatrixFirstColDiag(par_csr));
  std::vector<int> position(a.values.size(), -1);
  for (int r = 0; r < a.rows; ++r) {
    for (int q = a.row_ptr[static_cast<std::size_t>(r)]; q < a.row_ptr[static_cast<std::size_t>(r) + 1]; ++q) {
      const long col = a.cols[static_cast<std::size_t>(q)];
      int& at = position[static_cast<std::size_t>(q)];
      for (HYPRE_Int h = di[r]; h < di[r + 1] && at < 0; ++h) {
        if (static_cast<long>(dj[h]) + first == col) at = static_cast<int>(h);
      }
      for (HYPRE_Int h = has_offd ? oi[r] : 0; has_offd && h < oi[r + 1] && at < 0; ++h) {
        if (static_cast<long>(offd_global[oj[h]]) == col) at = static_cast<int>(diag_nnz + h);
      }
      if (at < 0) return {};   // an entry hypre dropped or moved (it keeps explicit zeros, but be safe)
    }
  }
  return position;
}

std::pair<double, double> HypreMatrix::rhs_and_residual_norms(const HypreVector& b, const HypreVector& x,
                                                              HypreVector& r) const {
  HYPRE_ParVectorCopy(b.par(), r.par());
  HYPRE_ParCSRMatrixMatvec(-1.0, par(), x.par(), 1.0, r.par());
  double b2 = 0.0;
  double r2 = 0.0;
  HYPRE_ParVectorInnerProd(b.par(), b.par(), &b2);
  HYPRE_ParVectorInnerProd(r.par(), r.par(), &r2);
  return {std::sqrt(b2), std::sqrt(r2)};
}

}  // namespace hs::unresolved
