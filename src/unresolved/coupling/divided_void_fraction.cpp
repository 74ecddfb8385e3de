// SPDX-License-Identifier: MIT
// The "divided" particle-to-grid map of CFDEM: marker positions, cell location, void fraction.
#include "unresolved/coupling/divided_void_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <omp.h>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "unresolved/coupling/diffusion_smoothing.hpp"

namespace hs::unresolved {
namespace {

using hs::common::Vec3;

/// Volume-centroid radius of the shell between a and b (unit sphere): (3/4)(b^4 - a^4)/(b^3 - a^3).
double centroid_radius(double a, double b) {
  return 0.75 * (std::pow(b, 4) - std::pow(a, 4)) / (std::pow(b, 3) - std::pow(a, 3));
}

std::array<Vec3, kMarkersPerSphere> make_markers() {
  std::array<Vec3, kMarkersPerSphere> m{};
  const double r1 = std::cbrt(1.0 / 29.0);
  const double r2 = std::cbrt(15.0 / 29.0);
  const std::array<double, 2> radius{centroid_radius(r1, r2), centroid_radius(r2, 1.0)};
  const double s = std::sqrt(0.5);   // sin 45 deg = cos 45 deg
  std::size_t k = 1;   // m[0] is the centre
  for (const double r : radius) {
    for (const double cz : {s, -s}) {        // polar angle 45 and 135 deg
      for (const double az : {45.0, 135.0, 225.0, 315.0}) {
        const double phi = az * std::numbers::pi / 180.0;
        m[k++] = Vec3{r * s * std::cos(phi), r * s * std::sin(phi), r * cz};
      }
    }
    for (int a = 0; a < 3; ++a) {
      for (const double sign : {1.0, -1.0}) {
        Vec3 v{};
        v[a] = sign * r;
        m[k++] = v;
      }
    }
  }
  return m;
}

}  // namespace

const std::array<Vec3, kMarkersPerSphere>& divided_markers() {
  static const std::array<Vec3, kMarkersPerSphere> markers = make_markers();
  return markers;
}

DividedMap::DividedMap(const FvmGrid& grid)
    : grid_(grid), cell_volume_m3_(std::pow(grid.dx_m(), 3)), slabs_(grid.slabs() != nullptr) {
  if (grid.fluid_fractions().data().size() >= kNowhere) {   // the flat indices are stored in 32 bits
    throw hs::common::ConfigError(fmt::format("coupling: {} FVM cells on one rank; at most {} (run on more MPI ranks)",
                                              grid.fluid_fractions().data().size(), kNowhere - 1));
  }
}

std::optional<std::array<long, 3>> DividedMap::global_cell(const Vec3& x_m) const {
  const hs::common::Box3& box = grid_.box_m();
  const auto& n = grid_.global_cells();
  const Vec3 w = grid_.wrap(x_m);   // along the periodic axes
  std::array<long, 3> g{};
  for (int a = 0; a < 3; ++a) {
    const auto na = static_cast<long>(n[static_cast<std::size_t>(a)]);
    if (slabs_ && a == 2 && grid_.periodic(2)) {   // not wrapped: the image beyond the seam is another row's
      g[2] = static_cast<long>(std::floor((x_m[2] - box.lo[2]) / grid_.dx_m()));
      continue;
    }
    const double s = (w[a] - box.lo[a]) / grid_.dx_m();
    if (!(s >= 0.0) || s > static_cast<double>(na)) return std::nullopt;
    g[static_cast<std::size_t>(a)] = std::min(static_cast<long>(s), na - 1);
  }
  return g;
}

std::size_t DividedMap::local_index(const std::array<long, 3>& g) const {
  const long k = g[2] - grid_.first_plane();
  if (k < 0 || k >= grid_.cells()[2]) return kElsewhere;
  return grid_.fluid_fractions().index(static_cast<int>(g[0]), static_cast<int>(g[1]), static_cast<int>(k));
}

bool DividedMap::has_fluid(const std::array<long, 3>& g) const {
  const std::size_t here = local_index(g);
  if (here != kElsewhere) return grid_.fluid_fractions()[here] > 0.0;
  const long below = grid_.first_plane() - 1 - g[2];
  const long above = g[2] - grid_.first_plane() - grid_.cells()[2];
  const long d = below >= 0 ? below : above;
  if (d >= cached_planes_) {
    throw hs::common::NumericalError("coupling: a marker reached beyond the planes cached next to this block");
  }
  const auto plane = static_cast<std::size_t>(grid_.cells()[0]) * static_cast<std::size_t>(grid_.cells()[1]);
  const std::size_t at = static_cast<std::size_t>(d) * plane + static_cast<std::size_t>(g[1]) * static_cast<std::size_t>(grid_.cells()[0]) +
                         static_cast<std::size_t>(g[0]);
  return (below >= 0 ? fluid_below_ : fluid_above_)[at] != 0;
}

void DividedMap::cache_neighbour_fluid(int planes) {
  const auto& n = grid_.cells();
  const long n_global = grid_.global_cells()[2];
  fluid_below_.clear();
  fluid_above_.clear();
  for (int d = 0; d < planes; ++d) {
    for (const int side : {0, 1}) {
      long k = side == 0 ? grid_.first_plane() - 1 - d : grid_.first_plane() + n[2] + d;
      if (grid_.periodic(2)) k = ((k % n_global) + n_global) % n_global;
      const bool inside = k >= 0 && k < n_global;   // else outside the box: global_cell() never gives it
      std::vector<std::uint8_t>& out = side == 0 ? fluid_below_ : fluid_above_;
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          out.push_back(inside && grid_.fluid_fraction_of_cell(i, j, static_cast<int>(k)) > 0.0 ? 1 : 0);
        }
      }
    }
  }
  cached_planes_ = planes;
}

std::size_t DividedMap::marker_cell(const Vec3& x, const std::array<long, 3>& centre) const {
  const auto g = global_cell(x);
  if (!g) return local_index(centre);
  const std::size_t here = local_index(*g);
  const std::size_t centre_here = local_index(centre);
  if (here == kElsewhere && centre_here == kElsewhere) return kElsewhere;   // a neighbour's either way
  return has_fluid(*g) ? here : centre_here;
}

void DividedMap::locate_markers(std::size_t i, const Vec3& x, double r, const std::array<long, 3>& centre) {
  const auto& markers = divided_markers();
  for (int m = 0; m < kMarkersPerSphere; ++m) {
    const std::size_t c = marker_cell(x + r * markers[static_cast<std::size_t>(m)], centre);
    cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)] = c == kElsewhere ? kNowhere : static_cast<std::uint32_t>(c);
  }
}

bool DividedMap::locate_markers_inside(std::size_t i, const Vec3& x, double r, const std::array<long, 3>& centre) {
  const hs::common::Box3& box = grid_.box_m();
  const double dx = grid_.dx_m();
  const auto& n = grid_.cells();
  const auto& n_global = grid_.global_cells();
  // The cube's lowest and highest cells along each axis, by global_cell()'s arithmetic (monotone in the position, so
  // every marker, within the unit sphere, falls between them): inside the box, and along z in this block's planes.
  for (int a = 0; a < 3; ++a) {
    const auto u = static_cast<std::size_t>(a);
    const double lo = (x[a] - r - box.lo[a]) / dx;
    const double hi = (x[a] + r - box.lo[a]) / dx;
    if (!(lo >= 0.0) || !(hi < static_cast<double>(n_global[u]))) return false;
    if (a == 2 && (static_cast<long>(lo) < grid_.first_plane() || static_cast<long>(hi) >= grid_.first_plane() + n[2])) return false;
  }
  const std::size_t centre_here = local_index(centre);
  const BlockField<double>& ff = grid_.fluid_fractions();
  const auto& markers = divided_markers();
  for (int m = 0; m < kMarkersPerSphere; ++m) {
    const Vec3 p = x + r * markers[static_cast<std::size_t>(m)];
    const auto ci = static_cast<int>((p[0] - box.lo[0]) / dx);
    const auto cj = static_cast<int>((p[1] - box.lo[1]) / dx);
    const auto ck = static_cast<int>(static_cast<long>((p[2] - box.lo[2]) / dx) - grid_.first_plane());
    const std::size_t here = ff.index(ci, cj, ck);
    cells_[i * kMarkersPerSphere + static_cast<std::size_t>(m)] = static_cast<std::uint32_t>(ff[here] > 0.0 ? here : centre_here);
  }
  return true;
}

void DividedMap::sort_rows_by_id(const std::vector<std::int64_t>& id) {
  const bool fits = std::all_of(by_id_.begin(), by_id_.end(), [&](std::uint32_t i) { return id[i] >= 0 && id[i] <= INT64_C(0xffffffff); });
  if (!fits) {
    std::sort(by_id_.begin(), by_id_.end(), [&](std::uint32_t a, std::uint32_t b) { return id[a] != id[b] ? id[a] < id[b] : a < b; });
    return;
  }
  // by_id_ holds the rows ascending; each stable pass keeps that order among equal keys (one id twice: its images
  // on both sides of one neighbour), so the result is sorted by (id, row).
  id_scratch_.resize(by_id_.size());
  std::vector<std::uint32_t> count(65537);
  for (const int shift : {0, 16}) {
    std::fill(count.begin(), count.end(), 0);
    const auto digit = [&](std::uint32_t row) { return (static_cast<std::uint64_t>(id[row]) >> shift) & 0xffffu; };
    for (const std::uint32_t row : by_id_) ++count[digit(row) + 1];
    for (std::size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
    for (const std::uint32_t row : by_id_) id_scratch_[count[digit(row)]++] = row;
    by_id_.swap(id_scratch_);
  }
}

void DividedMap::locate(const ParticleStore& particles) {
  n_owned_ = particles.n_owned();
  // The rows this block deposits, by id: its particles and, on slabs, the neighbours' (a local periodic image is not
  // one: the markers of the particle it copies wrap along x and y by themselves).
  by_id_.clear();
  double largest_radius = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (i >= n_owned_ && !(slabs_ && particles.coupling_row(i) == i)) continue;
    by_id_.push_back(static_cast<std::uint32_t>(i));
    largest_radius = std::max(largest_radius, particles.radius_m()[i]);
  }
  sort_rows_by_id(particles.id());
  if (slabs_) {   // the neighbours' cells a marker of a sphere centred in this block can reach (0.9 r), and one more
    const int planes = static_cast<int>(std::ceil(largest_radius / grid_.dx_m())) + 1;
    if (planes > cached_planes_) cache_neighbour_fluid(planes);
  }
  cells_.assign(particles.size() * kMarkersPerSphere, kNowhere);
  const auto& pos = particles.position_m();
  const auto n = static_cast<std::int64_t>(by_id_.size());
  bool lost = false;
#pragma omp parallel for schedule(static) reduction(|| : lost) if (n > 4096)
  for (std::int64_t q = 0; q < n; ++q) {
    const std::size_t i = by_id_[static_cast<std::size_t>(q)];
    const Vec3 x{pos[0][i], pos[1][i], pos[2][i]};
    const auto centre = global_cell(x);
    if (!centre) {
      lost = lost || i < n_owned_;   // thrown below: an exception must not leave an OpenMP region
      continue;
    }
    const double r = particles.radius_m()[i];
    if (!locate_markers_inside(i, x, r, *centre)) locate_markers(i, x, r, *centre);
  }
  if (lost) throw hs::common::NumericalError("coupling: a particle centre left the fluid grid");
  sort_by_cell(grid_.fluid_fractions().data().size());
}

void DividedMap::sort_by_cell(std::size_t n_cells) {
  // Counting sort of the (sphere, cell) pairs, stable in the sphere's place q in id order (particle by_id_[q]): each
  // thread counts a contiguous range of q; a cell's pairs from thread 0 come first, then thread 1's, ..., so the order
  // is ascending q at any thread count. Markers left to a neighbour are skipped.
  const std::size_t n_particles = by_id_.size();
  const int n_threads = n_particles * kMarkersPerSphere > 16 * static_cast<std::size_t>(kParallelCells) ? omp_get_max_threads() : 1;
  thread_counts_.resize(static_cast<std::size_t>(n_threads));   // kept: a million cells' counts would fault in anew
  start_.assign(n_cells + 1, 0);
  // The pairs of a range of spheres, each sphere's distinct cells in the order they first appear, found once and
  // scattered by the second pass.
  const auto find_pairs = [&](std::size_t lo, std::size_t hi, std::vector<Pair>& pairs) {
    pairs.clear();
    for (std::size_t q = lo; q < hi; ++q) {
      const std::uint32_t row = by_id_[q];
      const std::uint32_t* cells = &cells_[std::size_t{row} * kMarkersPerSphere];
      const std::size_t first = pairs.size();
      for (int m = 0; m < kMarkersPerSphere; ++m) {
        if (cells[m] == kNowhere) continue;
        std::size_t d = first;
        while (d < pairs.size() && pairs[d].cell != cells[m]) ++d;
        if (d == pairs.size()) pairs.push_back({.cell = cells[m], .row = row, .markers = 0});
        ++pairs[d].markers;
      }
    }
  };
  thread_pairs_.resize(static_cast<std::size_t>(n_threads));
#pragma omp parallel num_threads(n_threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t lo = n_particles * t / static_cast<std::size_t>(n_threads);
    const std::size_t hi = n_particles * (t + 1) / static_cast<std::size_t>(n_threads);
    std::vector<Pair>& pairs = thread_pairs_[t];
    find_pairs(lo, hi, pairs);
    std::vector<std::uint32_t>& mine = thread_counts_[t];
    mine.assign(n_cells, 0);
    for (const Pair& e : pairs) ++mine[e.cell];
#pragma omp barrier
#pragma omp single
    {
      std::uint32_t total = 0;
      for (std::size_t c = 0; c < n_cells; ++c) {
        start_[c] = total;
        for (int u = 0; u < n_threads; ++u) {   // becomes each thread's first slot in cell c
          std::uint32_t& n_here = thread_counts_[static_cast<std::size_t>(u)][c];
          const std::uint32_t first = total;
          total += n_here;
          n_here = first;
        }
      }
      start_[n_cells] = total;
      rows_.resize(total);
      markers_.resize(total);
    }
    for (const Pair& e : pairs) {
      const std::uint32_t slot = mine[e.cell]++;
      rows_[slot] = e.row;
      markers_[slot] = e.markers;
    }
  }
  occupied_.clear();
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (start_[c + 1] > start_[c]) occupied_.push_back(c);
  }
}

double DividedMap::void_fraction(const ParticleStore& particles, double eps_min, BlockField<double>& eps,
                                 DiffusionSmoothing* smoothing) const {
  BlockField<double> solid(grid_.cells(), 0.0);
  for_each_cell([&](std::size_t c, std::size_t i, int markers) {
    const double r = particles.radius_m()[i];
    solid[c] += 4.0 / 3.0 * std::numbers::pi * r * r * r * markers / kMarkersPerSphere;
  });
  // Every stored cell (ghosts too: the solver refills them before use); the clip below walks the interior.
  const std::vector<double>& ff = grid_.fluid_fractions().data();
  for (std::size_t c = 0; c < ff.size(); ++c) {
    if (ff[c] > 0.0) solid[c] /= fluid_volume_m3(c);
  }
  if (smoothing != nullptr) smoothing->smooth(solid);   // conserved: what the particles put on the grid stays there
  for (std::size_t c = 0; c < ff.size(); ++c) {
    if (ff[c] > 0.0) eps[c] = 1.0 - solid[c];
  }
  return clip_void_fraction(eps_min, eps);
}

double DividedMap::clip_void_fraction(double eps_min, BlockField<double>& eps) const {
  double lost_m3 = 0.0;
  const BlockField<double>& ff = grid_.fluid_fractions();
  const auto& n = grid_.cells();
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const std::size_t c = ff.index(i, j, k);
        if (ff[c] <= 0.0) {
          eps[c] = 1.0;
          continue;
        }
        if (eps[c] < eps_min) lost_m3 += (eps_min - eps[c]) * fluid_volume_m3(c);
        eps[c] = std::max(eps[c], eps_min);
      }
    }
  }
  return lost_m3;
}

}  // namespace hs::unresolved
