// SPDX-License-Identifier: MIT
// The D3Q19 lattice Boltzmann fluid: construction, time step and node access.
#include "resolved/lbm/fluid_lattice.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <utility>

namespace hs::resolved {
namespace {

/// Streaming (non-temporal) stores pay off only when the two population arrays are far larger than the last-level
/// cache, which they then bypass; 256 MiB is beyond the L3 of current server CPUs (32-256 MiB per socket).
constexpr std::size_t kStreamingStoreBytes = std::size_t{256} << 20;
/// Below this many fluid nodes a step takes less than ~0.1 ms on one core and stays single-threaded: an OpenMP
/// parallel region costs microseconds on an idle machine and whole scheduler slices on an oversubscribed one.
constexpr std::size_t kMinNodesForThreads = 32768;

}  // namespace

FluidLattice::FluidLattice(const LatticeSpec& spec, MPI_Comm comm) : spec_(spec) {
  spec_.collision.validate();
  decomposition_ = std::make_unique<common::CartesianDecomposition>(
      common::DecompositionSpec{.global_nodes = spec.global_nodes,
                                .periodic = spec.periodic,
                                .ranks_per_axis = spec.ranks_per_axis,
                                .ghost = 1},
      comm);
  layout_ = decomposition_->layout();
  stride_ = (layout_.volume() + 7) / 8 * 8;
  halo_ = std::make_unique<common::HaloExchange>(*decomposition_);
  for (std::size_t i = 0; i < D3Q19::q; ++i) {
    offsets_[i] = layout_.offset(D3Q19::c[i][0], D3Q19::c[i][1], D3Q19::c[i][2]);
  }
  // Pull scheme: a ghost on the high face of axis a is read only along directions with c_a = -1, which the
  // high neighbour sends through its low face (and vice versa).
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < D3Q19::q; ++i) {
      const int ca = D3Q19::c[static_cast<std::size_t>(i)][static_cast<std::size_t>(a)];
      if (ca == -1) halo_components_[a][0].push_back(i);
      if (ca == 1) halo_components_[a][1].push_back(i);
    }
  }
}

void FluidLattice::set_shape(const common::Shape& shape, const ShapePlacement& placement, WallRule rule) {
  shape_ = &shape;
  placement_ = placement;
  wall_rule_ = rule;
}

void FluidLattice::set_face_wall_velocity(int axis, int side, const common::Vec3& u_lu) {
  face_wall_velocity_[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)] = u_lu;
}

void FluidLattice::set_velocity_inlet(int axis, int side, std::function<common::Vec3(const common::Vec3&)> profile) {
  if (spec_.periodic[static_cast<std::size_t>(axis)]) throw std::invalid_argument("velocity inlet on a periodic axis");
  open_faces_[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)] =
      OpenFace{.velocity_given = true, .profile = std::move(profile), .rho_lu = spec_.rho0_lu};
}

void FluidLattice::set_pressure_outlet(int axis, int side, double rho_lu) {
  if (spec_.periodic[static_cast<std::size_t>(axis)]) throw std::invalid_argument("pressure outlet on a periodic axis");
  open_faces_[static_cast<std::size_t>(axis)][static_cast<std::size_t>(side)] =
      OpenFace{.velocity_given = false, .profile = {}, .rho_lu = rho_lu};
}

void FluidLattice::enable_force_field() { force_field_.assign(3 * layout_.volume(), 0.0); }

void FluidLattice::initialize(const std::function<NodeInit(const common::Vec3&)>& init) {
  phase_.clear();
  inner_nodes_.clear();
  geometry_runs_.clear();
  classify_nodes();
  build_runs();
  build_open_nodes();
  build_wall_links();
  reduced_halo_ = open_nodes_.empty();
  if (aa() && !open_nodes_.empty()) {
    throw std::invalid_argument("FluidLattice: open faces (velocity inlet, pressure outlet) are not supported with "
                                "Streaming::aa; use Streaming::two_buffer");
  }
  src_.assign(D3Q19::q * stride_, 0.0);
  for (std::size_t n = 0; n < layout_.volume(); ++n) {
    const auto g = global_of(static_cast<std::ptrdiff_t>(n));
    NodeInit s{.rho_lu = spec_.rho0_lu, .u_lu = {}};
    if (init && flags_[n] != kShapeSolid && flags_[n] != kFaceSolid) {
      s = init(common::Vec3{static_cast<double>(g[0]), static_cast<double>(g[1]), static_cast<double>(g[2])});
    }
    for (int i = 0; i < D3Q19::q; ++i) {
      // AA starts in the swapped layout: f*_i(y) at A[opp(i)][y].
      const int slot = aa() ? D3Q19::opposite(i) : i;
      src_[static_cast<std::size_t>(slot) * stride_ + n] = equilibrium(i, s.rho_lu, s.u_lu);
    }
  }
  steps_ = 0;
  links_need_odd_parts_ = std::any_of(links_.begin(), links_.end(), [](const WallLink& l) { return l.e != 0.0; });
  if (aa()) {
    build_aa_layers();
    dst_ = AlignedDoubles();
    aa_halo_ = std::make_unique<AaHalo>(*decomposition_, stride_, aa_wrap_x() > 0);
    link_odd_parts_.assign(D3Q19::half * odd_part_nodes_, 0.0);
    // As the two-buffer scheme, whose `previous` buffer is the initial state before the first exchange: ghosts
    // hold f^eq of init() at their unwrapped positions, so no x wrapping here.
    AaLayout raw = aa_layout();
    raw.wrap_x = 0;
    capture_link_odd_parts(links_, src_.data(), raw, link_odd_parts_);
    for (const bool natural : {false, true}) {
      AaLayout layout = aa_layout();
      layout.natural = natural;
      aa_links_[natural ? 1 : 0] = resolve_aa_links(links_, layout);
    }
  } else {
    dst_ = src_;
  }
  complete_state();
}

void FluidLattice::complete_state() {
  exchange_halos();
  apply_boundaries();
}

void FluidLattice::exchange_halos() {
  if (aa()) {
    aa_exchange();
  } else if (reduced_halo_) {
    halo_->exchange(src_, halo_components_, stride_);
  } else {
    halo_->exchange(src_, D3Q19::q, stride_);
  }
}

void FluidLattice::apply_boundaries() {
  if (aa()) {
    // After a step the kernel has applied the fused links already; at initialize() all links are due.
    const std::size_t first = fused_links_done_ ? fused_links_ : 0;
    fused_links_done_ = false;
    apply_wall_links_aa(std::span<const AaWallLink>(aa_links_[steps_ % 2]).subspan(first), src_.data(), link_odd_parts_,
                        link_body_force());
    return;
  }
  apply_open_boundaries(open_nodes_, src_.data(), stride_);
  apply_wall_links(links_, src_.data(), dst_.data(), stride_, link_body_force());
}

void FluidLattice::step() {
  stream_collide();
  complete_state();
}

void FluidLattice::stream_collide() {
  if (aa()) {
    aa_stream_collide();
    return;
  }
  resolved::stream_collide(StreamCollideArgs{.src = src_.data(),
                                   .dst = dst_.data(),
                                   .volume = stride_,
                                   .offset = offsets_,
                                   .runs = runs_,
                                   .body_force = body_force_,
                                   .force_field = force_field_.empty() ? nullptr : force_field_.data(),
                                   .force_stride = layout_.volume(),
                                   .omega_plus = spec_.collision.omega_plus(),
                                   .omega_minus = spec_.collision.omega_minus(),
                                   .regularized = spec_.collision.regularizes(),
                                   .streaming_stores = streaming_stores(),
                                   .threaded = fluid_nodes_ >= kMinNodesForThreads,
                                   .inner = inner_relaxation()});
  std::swap(src_, dst_);
  ++steps_;
}

AaLayout FluidLattice::aa_layout() const {
  return AaLayout{.natural = steps_ % 2 == 1, .volume = stride_, .offset = offsets_.data(), .wrap_x = aa_wrap_x(),
                  .stride_y = layout_.stride_y()};
}

/// Along a periodic x axis held by this rank alone, the AA kernel wraps x itself: the strided x-ghost copies (one
/// cache line per value) are the costliest part of the ghost passes.
std::ptrdiff_t FluidLattice::aa_wrap_x() const {
  const bool self_periodic = decomposition_->neighbour(0, 0) == decomposition_->rank() &&
                             decomposition_->neighbour(0, 1) == decomposition_->rank();
  return self_periodic ? layout_.n[0] : 0;
}

/// Even steps_ (swapped layout) take a neighbour step, odd ones a local step. The kernel keeps the pre-collision odd
/// parts of the links' nodes as it updates them. The links away from the block faces are applied as soon as the
/// nodes they read are updated (their values depend on no ghost pass), while those are in cache; the others after
/// the ghost pass, in apply_boundaries().
void FluidLattice::aa_stream_collide() {
  // The links in the layout after this step (the natural one after an even step).
  const std::span<const AaWallLink> links(aa_links_[(steps_ + 1) % 2]);
  const std::function<void(int, LayerPair)> apply = [&](int z, LayerPair pair) {
    const std::size_t group = 2 * static_cast<std::size_t>(z) + (pair == LayerPair::with_above ? 1 : 0);
    const std::size_t k0 = layer_links_[group];
    apply_wall_links_aa(links.subspan(k0, layer_links_[group + 1] - k0), src_.data(), link_odd_parts_, link_body_force());
  };
  const bool fused = fused_links_ > 0;
  resolved::aa_stream_collide(
      AaStreamCollideArgs{.f = src_.data(),
                          .volume = stride_,
                          .offset = offsets_,
                          .runs = runs_,
                          .body_force = body_force_,
                          .force_field = force_field_.empty() ? nullptr : force_field_.data(),
                          .force_stride = layout_.volume(),
                          .omega_plus = spec_.collision.omega_plus(),
                          .omega_minus = spec_.collision.omega_minus(),
                          .regularized = spec_.collision.regularizes(),
                          .threaded = fluid_nodes_ >= kMinNodesForThreads,
                          .wrap_x = aa_wrap_x(),
                          .stride_y = layout_.stride_y(),
                          .layer_runs = fused ? &layer_runs_ : nullptr,
                          .after_layers = fused ? &apply : nullptr,
                          .odd_parts = links_need_odd_parts_ ? link_odd_parts_.data() : nullptr,
                          .odd_stride = odd_part_nodes_,
                          .inner = inner_relaxation()},
      steps_ % 2 == 0 ? AaStep::neighbour : AaStep::local);
  fused_links_done_ = true;
  ++steps_;
}

/// Swapped layout (before a neighbour step): fill the ghosts the step reads. Natural layout (after one): fold the
/// ghost slots it wrote back to their owners.
void FluidLattice::aa_exchange() {
  if (steps_ % 2 == 0) {
    aa_halo_->fill(src_);
  } else {
    aa_halo_->fold(src_);
  }
}

bool FluidLattice::streaming_stores() const {
  switch (spec_.store_mode) {
    case StoreMode::ordinary: return false;
    case StoreMode::streaming: return true;
    case StoreMode::automatic: break;
  }
  return 2 * src_.size() * sizeof(double) > kStreamingStoreBytes;
}

void FluidLattice::run(long steps) {
  for (long s = 0; s < steps; ++s) step();
}

double FluidLattice::population(int x, int y, int z, int i) const {
  const auto ii = static_cast<std::size_t>(i);
  // f_i(x) = f*_i(x - c_i), wherever the scheme keeps it.
  if (aa()) return src_[aa_layout().slot(i, index(x, y, z) - offsets_[ii])];
  return src_[ii * stride_ + static_cast<std::size_t>(index(x, y, z) - offsets_[ii])];
}

Populations FluidLattice::populations(int x, int y, int z) const {
  Populations f{};
  for (int i = 0; i < D3Q19::q; ++i) f[static_cast<std::size_t>(i)] = population(x, y, z, i);
  return f;
}

common::Vec3 FluidLattice::force(int x, int y, int z) const {
  common::Vec3 f = body_force_;
  if (!force_field_.empty()) {
    const auto n = static_cast<std::size_t>(index(x, y, z));
    const std::size_t v = layout_.volume();
    f += common::Vec3{force_field_[n], force_field_[v + n], force_field_[2 * v + n]};
  }
  return f;
}

NodeMoments FluidLattice::moments(int x, int y, int z) const {
  return resolved::moments(populations(x, y, z), force(x, y, z));
}

SymTensor FluidLattice::viscous_stress(int x, int y, int z) const {
  return resolved::viscous_stress(populations(x, y, z), force(x, y, z), tau_at(x, y, z));
}

void FluidLattice::add_force(int x, int y, int z, const common::Vec3& f_lu) {
  const auto n = static_cast<std::size_t>(index(x, y, z));
  const std::size_t v = layout_.volume();
  force_field_.at(n) += f_lu.x;
  force_field_.at(v + n) += f_lu.y;
  force_field_.at(2 * v + n) += f_lu.z;
}

void FluidLattice::restore_raw_populations(std::span<const double> f, long steps) {
  if (f.size() != src_.size()) throw std::invalid_argument("restore_raw_populations: the checkpoint is of another lattice");
  if (steps < 0) throw std::invalid_argument("restore_raw_populations: a negative step count (a damaged checkpoint)");
  std::copy(f.begin(), f.end(), src_.begin());
  steps_ = steps;
}

void FluidLattice::clear_force_field() { std::fill(force_field_.begin(), force_field_.end(), 0.0); }

std::array<int, 3> FluidLattice::global_of(std::ptrdiff_t n) const {
  auto c = layout_.coords(n);
  const auto& off = decomposition_->offset();
  for (std::size_t a = 0; a < 3; ++a) c[a] += off[a];
  return c;
}

}  // namespace hs::resolved
