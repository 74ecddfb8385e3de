// SPDX-License-Identifier: MIT
// Linked-cell construction of the half Verlet list, history carry-over and the rebuild criterion.
#include "unresolved/dem/neighbor_list.hpp"
#include "unresolved/dem/parallel_threshold.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "common/errors.hpp"
#include "unresolved/dem/cell_grid.hpp"

namespace hs::unresolved {
namespace {

/// Counting sort of particles [0, n) into the cells of `grid`: items of cell c are [start[c], start[c+1]).
void bin_particles(const ParticleStore& p, std::size_t n, const CellGrid& grid, std::vector<std::uint32_t>& start,
                   std::vector<std::uint32_t>& items) {
  const auto& pos = p.position_m();
  std::vector<int> cell(n);
  start.assign(static_cast<std::size_t>(grid.n_cells()) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = grid.index_of(pos[0][i], pos[1][i], pos[2][i]);
    ++start[static_cast<std::size_t>(cell[i]) + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  items.resize(n);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) items[fill[static_cast<std::size_t>(cell[i])]++] = static_cast<std::uint32_t>(i);
}

/// Cells allowed for n particles: a few per particle keeps the grid memory proportional to the particles.
double cell_budget(std::size_t n) { return 27.0 + 4.0 * static_cast<double>(n); }

}  // namespace

std::vector<std::size_t> cell_sort_order(const ParticleStore& particles, const Domain& domain, double cell_m) {
  const CellGrid grid(domain.box.lo, domain.box.hi, cell_m, cell_budget(particles.n_owned()));
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;
  bin_particles(particles, particles.n_owned(), grid, start, items);
  return {items.begin(), items.end()};
}

ContactHistory NeighborList::extract_history(const ParticleStore& particles) const {
  ContactHistory h;
  const auto& id = particles.id();
  for (std::size_t i = 0; i < n_owned(); ++i) {
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const auto& s = shear_[k];
      if (s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0) continue;
      h.keys.emplace_back(id[i], id[neighbors_[k]]);
      h.shear_m.push_back(s);
    }
  }
  std::vector<std::size_t> order(h.keys.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h.keys[a] < h.keys[b]; });
  ContactHistory sorted;
  for (std::size_t k : order) {
    sorted.keys.push_back(h.keys[k]);
    sorted.shear_m.push_back(h.shear_m[k]);
  }
  return sorted;
}

void NeighborList::build(const ParticleStore& p, const hs::common::Vec3& lo_m, const hs::common::Vec3& hi_m,
                         const ContactHistory& history) {
  const std::size_t n_owned = p.n_owned();
  double r_max = 0.0;
  for (double r : p.radius_m()) r_max = std::max(r_max, r);
  const double cutoff = 2.0 * r_max + skin_m_;
  const CellGrid grid(lo_m, hi_m, cutoff, cell_budget(p.size()));
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;
  bin_particles(p, p.size(), grid, start, items);

  const auto& pos = p.position_m();
  const auto& rad = p.radius_m();
  const auto& id = p.id();
  std::vector<std::uint32_t> count(n_owned + 1, 0);
  const int n_threads = static_cast<std::int64_t>(n_owned) > omp_min_particles ? omp_get_max_threads() : 1;
  std::vector<std::vector<std::uint32_t>> local(static_cast<std::size_t>(n_threads));
#pragma omp parallel num_threads(n_threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t lo = n_owned * t / static_cast<std::size_t>(n_threads);
    const std::size_t hi = n_owned * (t + 1) / static_cast<std::size_t>(n_threads);
    auto& out = local[t];
    for (std::size_t i = lo; i < hi; ++i) {
      const int cx = grid.cell_coord(0, pos[0][i]), cy = grid.cell_coord(1, pos[1][i]), cz = grid.cell_coord(2, pos[2][i]);
      const std::size_t before = out.size();
      for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, grid.n(2) - 1); ++z) {
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, grid.n(1) - 1); ++y) {
          for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, grid.n(0) - 1); ++x) {
            const auto c = static_cast<std::size_t>(grid.index(x, y, z));
            for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
              const std::uint32_t j = items[k];
              if (id[j] <= id[i]) continue;
              const double dx = pos[0][i] - pos[0][j], dy = pos[1][i] - pos[1][j], dz = pos[2][i] - pos[2][j];
              const double rc = rad[i] + rad[j] + skin_m_;
              if (dx * dx + dy * dy + dz * dz < rc * rc) out.push_back(j);
            }
          }
        }
      }
      count[i + 1] = static_cast<std::uint32_t>(out.size() - before);
    }
  }
  offsets_.assign(n_owned + 1, 0);
  for (std::size_t i = 0; i < n_owned; ++i) offsets_[i + 1] = offsets_[i] + count[i + 1];
  neighbors_.clear();
  neighbors_.reserve(offsets_[n_owned]);
  for (const auto& l : local) neighbors_.insert(neighbors_.end(), l.begin(), l.end());
  restore_history(p, history);
  pair_eff_.resize(neighbors_.size());
  const auto& mass = p.mass_kg();
  for (std::size_t i = 0; i < n_owned; ++i) {
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const std::size_t j = neighbors_[k];
      pair_eff_[k] = {rad[i] * rad[j] / (rad[i] + rad[j]), mass[i] * mass[j] / (mass[i] + mass[j])};
    }
  }
  for (int a = 0; a < 3; ++a) x_at_build_[a].assign(pos[a].begin(), pos[a].begin() + static_cast<std::ptrdiff_t>(n_owned));
  ++n_builds_;
}

void NeighborList::restore_history(const ParticleStore& p, const ContactHistory& history) {
  shear_.assign(neighbors_.size(), {0.0, 0.0, 0.0});
  if (history.keys.empty()) return;
  const auto& id = p.id();
  const auto n = static_cast<std::int64_t>(n_owned());
#pragma omp parallel for schedule(static) if (n > omp_min_particles)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const std::pair<std::int64_t, std::int64_t> key{id[i], id[neighbors_[k]]};
      const auto it = std::lower_bound(history.keys.begin(), history.keys.end(), key);
      if (it != history.keys.end() && *it == key) shear_[k] = history.shear_m[static_cast<std::size_t>(it - history.keys.begin())];
    }
  }
}

bool NeighborList::needs_rebuild(const ParticleStore& p) const {
  const auto& pos = p.position_m();
  const auto n = static_cast<std::int64_t>(p.n_owned());
  if (static_cast<std::size_t>(n) != n_owned()) return true;
  double max_d2 = 0.0;
#pragma omp parallel for reduction(max : max_d2) schedule(static) if (n > omp_min_particles)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double dx = pos[0][i] - x_at_build_[0][i], dy = pos[1][i] - x_at_build_[1][i],
                 dz = pos[2][i] - x_at_build_[2][i];
    const double d2 = dx * dx + dy * dy + dz * dz;
    max_d2 = std::isfinite(d2) ? std::max(max_d2, d2) : HUGE_VAL;
  }
  if (max_d2 == HUGE_VAL) throw hs::common::NumericalError("DEM: a particle position became non-finite");
  return 4.0 * max_d2 > skin_m_ * skin_m_;
}

}  // namespace hs::unresolved
