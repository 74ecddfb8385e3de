// SPDX-License-Identifier: MIT
#include "unresolved/coupling/diffusion_smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/SparseCholesky>
#include <fmt/format.h>
#include <mpi.h>

#include "common/errors.hpp"

namespace hs::unresolved {

namespace {
constexpr double kRelativeTolerance = 1e-13;
constexpr int kMaxIterations = 1000;

/// y = A x for the K interleaved columns, and pap_j = sum_r x_rj y_rj in the same pass (the CG's p . A p).
template <std::size_t K>
void apply_dot(const std::vector<double>& diagonal, const std::vector<std::size_t>& row_start,
               const std::vector<std::size_t>& neighbour, const std::vector<double>& coefficient,
               const std::vector<double>& x, std::vector<double>& y, std::array<double, K>& dot) {
  const std::size_t rows = diagonal.size();
  for (std::size_t r = 0; r < rows; ++r) {
    std::array<double, K> s{};
    for (std::size_t j = 0; j < K; ++j) s[j] = diagonal[r] * x[r * K + j];
    for (std::size_t e = row_start[r]; e < row_start[r + 1]; ++e) {
      const double a = coefficient[e];
      const double* xn = &x[neighbour[e] * K];
      for (std::size_t j = 0; j < K; ++j) s[j] -= a * xn[j];
    }
    for (std::size_t j = 0; j < K; ++j) {
      y[r * K + j] = s[j];
      dot[j] += x[r * K + j] * s[j];
    }
  }
}
}  // namespace

struct DiffusionSmoothing::Factor {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
};

struct DiffusionSmoothing::Halo {
  MPI_Comm comm = MPI_COMM_NULL;
  std::array<int, 2> neighbour{MPI_PROC_NULL, MPI_PROC_NULL};   // below, above (MPI_PROC_NULL: the box's wall)
  // To the neighbour below go the rows of plane 0 (its ghost plane n), above those of plane n - 1 (its plane -1).
  std::array<std::vector<std::size_t>, 2> send;
  // The ghost rows of plane -1 (from below) and of plane n (from above): first row and count, after the own rows.
  std::array<std::size_t, 2> first{};
  std::array<std::size_t, 2> count{};
};

DiffusionSmoothing::DiffusionSmoothing(const FvmGrid& grid, double length_m, Method method) : length_m_(length_m) {
  if (!(length_m > 0.0) || !std::isfinite(length_m)) {
    throw hs::common::ConfigError(fmt::format("coupling: smoothing length {} m must be > 0", length_m));
  }
  const auto& n = grid.cells();
  const auto& fraction = grid.fluid_fractions();
  const double dx = grid.dx_m();
  // Compact rows: the interior cells with fluid, in flat-index order.
  std::vector<long> row_of(fraction.data().size(), -1);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t c = fraction.index(i, j, k);
        if (fraction[c] <= 0.0) continue;
        row_of[c] = static_cast<long>(cell_index_.size());
        cell_index_.push_back(c);
        volume_.push_back(fraction[c] * dx * dx * dx);
      }
    }
  }
  // Several slabs: the neighbours' fluid cells next to the block become ghost rows after the own ones (their fluid
  // fractions are in the grid's ghost planes, the whole grid's to the bit, so both sides list the same cells in the
  // same order), and the block's first and last planes' rows are what it sends.
  const hs::common::CartesianDecomposition* slabs = grid.slabs();
  if (slabs != nullptr && slabs->ranks_per_axis()[2] > 1) {
    auto halo = std::make_shared<Halo>();
    halo->comm = slabs->comm();
    std::size_t next = cell_index_.size();
    for (int side = 0; side < 2; ++side) {
      const auto s = static_cast<std::size_t>(side);
      halo->neighbour[s] = slabs->neighbour(2, side);
      halo->first[s] = next;
      if (halo->neighbour[s] == MPI_PROC_NULL) continue;
      const int ghost_plane = side == 0 ? -1 : n[2];
      const int own_plane = side == 0 ? 0 : n[2] - 1;
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          if (const std::size_t g = fraction.index(i, j, ghost_plane); fraction[g] > 0.0) row_of[g] = static_cast<long>(next++);
          if (const long r = row_of[fraction.index(i, j, own_plane)]; r >= 0) halo->send[s].push_back(static_cast<std::size_t>(r));
        }
      }
      halo->count[s] = next - halo->first[s];
    }
    halo_ = std::move(halo);
  }
  const double scale = length_m * length_m * dx;
  row_start_.push_back(0);
  for (std::size_t r = 0; r < cell_index_.size(); ++r) {
    // Recover (i, j, k) of the row's cell from its flat index.
    const std::size_t c = cell_index_[r];
    const long sy = fraction.stride(1);
    const long sz = fraction.stride(2);
    const std::array<int, 3> ijk{static_cast<int>(static_cast<long>(c) % sy) - 1,
                                 static_cast<int>((static_cast<long>(c) % sz) / sy) - 1,
                                 static_cast<int>(static_cast<long>(c) / sz) - 1};
    double diagonal = volume_[r];
    for (int a = 0; a < 3; ++a) {
      const int na = n[static_cast<std::size_t>(a)];
      for (const int side : {-1, 1}) {
        std::array<int, 3> nb = ijk;
        nb[static_cast<std::size_t>(a)] += side;
        const bool beyond = nb[static_cast<std::size_t>(a)] < 0 || nb[static_cast<std::size_t>(a)] >= na;
        if (beyond && halo_ && a == 2) {   // a neighbour's ghost row, or the box's wall
          if (halo_->neighbour[side < 0 ? 0 : 1] == MPI_PROC_NULL) continue;
        } else {
          if (beyond) {
            if (!grid.periodic(a)) continue;   // the box's own faces: walls and openings let nothing diffuse out
            nb[static_cast<std::size_t>(a)] = (nb[static_cast<std::size_t>(a)] + na) % na;
          }
          if (na == 1) continue;   // a one-cell periodic axis: the cell is its own neighbour
        }
        // The face between the two cells is the velocity node of the higher cell index (node 0 across a periodic wrap).
        const std::array<int, 3> face = side > 0 ? nb : ijk;
        const double area = grid.open_areas(a)(face[0], face[1], face[2]);
        const long other = row_of[fraction.index(nb[0], nb[1], nb[2])];
        if (area <= 0.0 || other < 0) continue;
        neighbour_.push_back(static_cast<std::size_t>(other));
        coefficient_.push_back(scale * area);
        diagonal += scale * area;
      }
    }
    diagonal_.push_back(diagonal);
    row_start_.push_back(neighbour_.size());
  }
  inverse_diagonal_.reserve(diagonal_.size());
  for (const double d : diagonal_) inverse_diagonal_.push_back(1.0 / d);
  const std::size_t rows = cell_index_.size();
  if (method == Method::conjugate_gradient || halo_ || rows == 0 || rows > kDirectMaxRows) return;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(rows + neighbour_.size());
  for (std::size_t r = 0; r < rows; ++r) {
    const auto row = static_cast<int>(r);
    entries.emplace_back(row, row, diagonal_[r]);
    for (std::size_t e = row_start_[r]; e < row_start_[r + 1]; ++e) {
      entries.emplace_back(row, static_cast<int>(neighbour_[e]), -coefficient_[e]);
    }
  }
  Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows));
  a.setFromTriplets(entries.begin(), entries.end());   // a repeated pair (a two-cell periodic axis) adds up
  auto factor = std::make_shared<Factor>();
  factor->ldlt.compute(a);
  if (factor->ldlt.info() == Eigen::Success) factor_ = std::move(factor);   // else CG, which needs no factor
}

bool DiffusionSmoothing::solve_direct(std::vector<double>& q, int columns) {
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const auto rows = static_cast<Eigen::Index>(cell_index_.size());
  Eigen::Map<RowMajor> x(q.data(), rows, columns);
  Eigen::MatrixXd b(rows, columns);
  for (Eigen::Index r = 0; r < rows; ++r) b.row(r) = volume_[static_cast<std::size_t>(r)] * x.row(r);
  const Eigen::MatrixXd solution = factor_->ldlt.solve(b);
  // The CG's own test on the result: |b - A x| <= 1e-13 |b| for every column.
  const auto k = static_cast<std::size_t>(columns);
  std::vector<double> xs(q.size());
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index j = 0; j < columns; ++j) xs[static_cast<std::size_t>(r) * k + static_cast<std::size_t>(j)] = solution(r, j);
  }
  for (Eigen::Index j = 0; j < columns; ++j) {
    double residual = 0.0;
    for (Eigen::Index r = 0; r < rows; ++r) {
      const auto ru = static_cast<std::size_t>(r);
      double s = diagonal_[ru] * xs[ru * k + static_cast<std::size_t>(j)];
      for (std::size_t e = row_start_[ru]; e < row_start_[ru + 1]; ++e) {
        s -= coefficient_[e] * xs[neighbour_[e] * k + static_cast<std::size_t>(j)];
      }
      residual += (b(r, j) - s) * (b(r, j) - s);
    }
    if (std::sqrt(residual) > kRelativeTolerance * b.col(j).norm()) return false;
  }
  q = std::move(xs);
  return true;
}

void DiffusionSmoothing::exchange_ghost_rows(std::vector<double>& x, std::size_t columns) const {
  if (!halo_) return;
  // Plane 0's rows go down while plane n's ghosts come from above (tag 0), then plane n - 1's go up while plane -1's
  // ghosts come from below (tag 1); at the box's wall MPI_PROC_NULL sends and receives nothing.
  std::vector<double> out;
  for (int side = 0; side < 2; ++side) {
    const auto s = static_cast<std::size_t>(side);
    const std::size_t from = 1 - s;   // the ghosts filled by this message: from the other side's neighbour
    out.clear();
    for (const std::size_t r : halo_->send[s]) out.insert(out.end(), x.data() + r * columns, x.data() + (r + 1) * columns);
    MPI_Sendrecv(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, halo_->neighbour[s], side,
                 x.data() + halo_->first[from] * columns, static_cast<int>(halo_->count[from] * columns), MPI_DOUBLE,
                 halo_->neighbour[from], side, halo_->comm, MPI_STATUS_IGNORE);
  }
}

template <std::size_t N>
void DiffusionSmoothing::sum_over_ranks(std::array<double, N>& values) const {
  if (halo_) MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(N), MPI_DOUBLE, MPI_SUM, halo_->comm);
}

template <std::size_t K>
int DiffusionSmoothing::solve(std::vector<double>& q) {
  // b = V q; the start x = q is exact where q is flat, so smooth regions converge at once. Each column j is its own
  // CG (its own alpha, beta, stopping test); only the pass over the operator is shared. A converged column is left
  // as it is, so its result does not depend on which other fields share the solve.
  const std::size_t rows = cell_index_.size();
  const std::size_t size = rows * K;
  // The operator reads its neighbours' values also from the ghost rows after the own ones (distributed).
  const std::size_t with_ghosts = halo_ ? (halo_->first[1] + halo_->count[1]) * K : size;
  r_.resize(size);
  z_.resize(size);
  p_.resize(with_ghosts);
  ap_.resize(size);
  q.resize(with_ghosts);
  std::vector<double>& x = q;
  exchange_ghost_rows(x, K);
  std::array<double, K> b_norm{};
  std::array<double, K> rz{};
  std::array<double, K> r_norm{};   // |r|^2, summed where r is updated (one pass fewer over the vectors)
  std::array<bool, K> active{};
  std::array<int, K> iterations{};
  std::array<double, K> unused_dot{};   // the start's A x; its x.Ax is not needed
  apply_dot<K>(diagonal_, row_start_, neighbour_, coefficient_, x, ap_, unused_dot);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t j = 0; j < K; ++j) {
      const std::size_t i = r * K + j;
      const double b = volume_[r] * q[i];
      b_norm[j] += b * b;
      r_[i] = b - ap_[i];
      z_[i] = r_[i] * inverse_diagonal_[r];
      p_[i] = z_[i];
      rz[j] += r_[i] * z_[i];
      r_norm[j] += r_[i] * r_[i];
    }
  }
  sum_over_ranks(b_norm);
  sum_over_ranks(rz);
  sum_over_ranks(r_norm);
  int remaining = 0;
  for (std::size_t j = 0; j < K; ++j) {
    b_norm[j] = std::sqrt(b_norm[j]);
    active[j] = b_norm[j] != 0.0;   // q = 0: x = 0 is the answer
    remaining += active[j] ? 1 : 0;
  }
  for (int it = 0; it < kMaxIterations; ++it) {
    for (std::size_t j = 0; j < K; ++j) {
      if (active[j] && std::sqrt(r_norm[j]) <= kRelativeTolerance * b_norm[j]) {
        active[j] = false;
        iterations[j] = it;
        --remaining;
      }
    }
    if (remaining == 0) return *std::max_element(iterations.begin(), iterations.end());
    std::array<double, K> pap{};
    exchange_ghost_rows(p_, K);
    apply_dot<K>(diagonal_, row_start_, neighbour_, coefficient_, p_, ap_, pap);
    sum_over_ranks(pap);
    std::array<double, K> alpha{};   // 0 for a converged column: its x and r stay
    for (std::size_t j = 0; j < K; ++j) alpha[j] = active[j] ? rz[j] / pap[j] : 0.0;
    std::array<double, K> rz_new{};
    r_norm = {};
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t j = 0; j < K; ++j) {
        const std::size_t i = r * K + j;
        x[i] += alpha[j] * p_[i];
        r_[i] -= alpha[j] * ap_[i];
        z_[i] = r_[i] * inverse_diagonal_[r];
        rz_new[j] += r_[i] * z_[i];
        r_norm[j] += r_[i] * r_[i];
      }
    }
    sum_over_ranks(rz_new);
    sum_over_ranks(r_norm);
    std::array<double, K> beta{};
    for (std::size_t j = 0; j < K; ++j) {
      if (!active[j]) continue;
      beta[j] = rz_new[j] / rz[j];
      rz[j] = rz_new[j];
    }
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t j = 0; j < K; ++j) p_[r * K + j] = z_[r * K + j] + beta[j] * p_[r * K + j];
    }
  }
  throw hs::common::NumericalError(fmt::format(
      "coupling: the smoothing solve did not reach a relative residual of {:.0e} in {} iterations (smoothing length "
      "{:.4g} m)", kRelativeTolerance, kMaxIterations, length_m_));
}

int DiffusionSmoothing::solve_columns(std::vector<double>& q, int columns) {
  switch (columns) {
    case 1: return solve<1>(q);
    case 2: return solve<2>(q);
    case 3: return solve<3>(q);
    case 4: return solve<4>(q);
    case 5: return solve<5>(q);
    case 6: return solve<6>(q);
    case 7: return solve<7>(q);
    case 8: return solve<8>(q);
    default: break;
  }
  throw hs::common::ConfigError(fmt::format("coupling: {} fields smoothed together; 1 to {} allowed", columns,
                                            kMaxColumns));
}

void DiffusionSmoothing::smooth(BlockField<double>& q) { smooth_together({&q}, {}); }

void DiffusionSmoothing::smooth(BlockField<hs::common::Vec3>& q) { smooth_together({}, {&q}); }

void DiffusionSmoothing::smooth_together(std::initializer_list<BlockField<double>*> scalars,
                                         std::initializer_list<BlockField<hs::common::Vec3>*> vectors) {
  const int columns = static_cast<int>(scalars.size() + 3 * vectors.size());
  const std::size_t rows = cell_index_.size();
  const auto k = static_cast<std::size_t>(columns);
  x_.resize(rows * k);
  // Gather: row r's columns are the scalars in order, then each vector's x, y, z.
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t c = cell_index_[r];
    std::size_t j = r * k;
    for (const BlockField<double>* f : scalars) x_[j++] = (*f)[c];
    for (const BlockField<hs::common::Vec3>* f : vectors) {
      for (int a = 0; a < 3; ++a) x_[j++] = (*f)[c][a];
    }
  }
  if (factor_ && columns > 0 && solve_direct(x_, columns)) {
    last_iterations_ = 0;
  } else {
    last_iterations_ = solve_columns(x_, columns);
  }
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t c = cell_index_[r];
    std::size_t j = r * k;
    for (BlockField<double>* f : scalars) (*f)[c] = x_[j++];
    for (BlockField<hs::common::Vec3>* f : vectors) {
      for (int a = 0; a < 3; ++a) (*f)[c][a] = x_[j++];
    }
  }
}

}  // namespace hs::unresolved
