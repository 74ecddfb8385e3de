// SPDX-License-Identifier: MIT
// The D3Q19 lattice Boltzmann fluid on one rank's block of an MPI Cartesian decomposition.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <mpi.h>

#include "common/geometry/shape.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "common/parallel/halo_exchange.hpp"
#include "common/vec3.hpp"
#include "resolved/lbm/aa_halo.hpp"
#include "resolved/lbm/aa_stream_collide.hpp"
#include "resolved/lbm/aligned_allocator.hpp"
#include "resolved/lbm/boundary_links.hpp"
#include "resolved/lbm/collision_params.hpp"
#include "resolved/lbm/equilibrium.hpp"
#include "resolved/lbm/stream_collide.hpp"

namespace hs::resolved {

/// How the kernel writes populations: `automatic` streams (non-temporal stores) when the arrays are far beyond cache.
enum class StoreMode { automatic, ordinary, streaming };

/// How populations stream. `two_buffer`: fused pull-stream + collide from one buffer into another (stream_collide.hpp).
/// `aa`: the in-place AA pattern on one buffer (aa_stream_collide.hpp): half the memory, and no write-allocate
/// traffic, so 19 + 19 doubles per node instead of 19 + 2 x 19 with ordinary stores. Supports periodic axes, MPI
/// blocks, half-way and Bouzidi walls (also moving) and the force field; not open faces (initialize() throws).
enum class Streaming { two_buffer, aa };

struct LatticeSpec {
  std::array<int, 3> global_nodes{};       // nodes per axis of the whole lattice
  std::array<bool, 3> periodic{};          // periodic axes; other axes end in walls or open faces
  CollisionParams collision;
  std::array<int, 3> ranks_per_axis{};     // 0 = let MPI choose
  double rho0_lu = 1.0;                    // reference density (initial state, moving-wall term)
  StoreMode store_mode = StoreMode::automatic;   // two_buffer only
  Streaming streaming = Streaming::two_buffer;
};

/// Where the lattice sits in the Shape's coordinates: global node (i, j, k) is at origin + spacing (i, j, k).
struct ShapePlacement {
  common::Vec3 origin;
  double spacing = 1.0;
};

/// Limits checked by the watchdog (check_health). Lattice Mach = |u| / c_s.
struct HealthLimits {
  double rho_min_lu = 0.5;
  double rho_max_lu = 1.5;
  double mach_max = 0.1;   // Krueger et al. 2017, section 7.3.3: compressibility errors grow as Ma^2
};

/// Initial state of one node: density and (half-force) velocity.
struct NodeInit {
  double rho_lu = 1.0;
  common::Vec3 u_lu;
};

/// The fluid solver. Populations are stored post-collision, structure-of-arrays, double precision, on the
/// local block plus one ghost layer, in two buffers (pull scheme) or, with Streaming::aa, in one buffer whose layout
/// alternates with the parity of steps_done() (AaLayout). Between steps the state is complete: the
/// ghosts are exchanged and the wall/open-boundary slots set, so every pre-collision population
/// f_i(x) = f*_i(x - c_i) can be read at any interior node (population(), moments(), viscous_stress()).
/// Non-periodic faces are walls (half-way bounce-back, optionally moving) unless made open.
/// Local node coordinates run 0..n-1 on this rank's block (layout().n); global = local + offset().
class FluidLattice {
 public:
  /// Collective over `comm`.
  FluidLattice(const LatticeSpec& spec, MPI_Comm comm);

  // ---- set-up, before initialize() ----
  /// Nodes outside `shape` become solid; links crossing its wall are closed by `rule`. `shape` is used during
  /// initialize() only. The wall is at rest. Nodes are classified at positions wrapped into the periodic box,
  /// wall fractions q are found along unwrapped links: exact for shapes invariant along the periodic axes.
  void set_shape(const common::Shape& shape, const ShapePlacement& placement, WallRule rule);
  /// Velocity (lattice units) of the half-way bounce-back wall on a non-periodic face (axis, side 0/1).
  void set_face_wall_velocity(int axis, int side, const common::Vec3& u_lu);
  /// Velocity inlet on a non-periodic face; `profile(global position in lattice units)` gives u.
  void set_velocity_inlet(int axis, int side, std::function<common::Vec3(const common::Vec3&)> profile);
  /// Pressure outlet on a non-periodic face at density rho_lu (p = c_s^2 rho).
  void set_pressure_outlet(int axis, int side, double rho_lu);
  /// Uniform body-force density (lattice units, rho dx/dt^2), e.g. the drive of a periodic channel.
  void set_body_force(const common::Vec3& force_lu) { body_force_ = force_lu; }
  [[nodiscard]] const common::Vec3& body_force() const { return body_force_; }
  /// Allocates a per-node force density field (zero), added to the body force (IBM spreading target).
  void enable_force_field();
  /// Classifies nodes, builds boundary links and sets f = f^eq(rho, u) from `init(global position lu)`.
  /// Collective.
  void initialize(const std::function<NodeInit(const common::Vec3&)>& init = {});

  // ---- a second fluid phase: the cytoplasm (docs/resolved-coupling.md, "The cytoplasm") ----
  /// The nodes of phase 1 relax with `inner` (its tau; model, magic and odd-rate bound as given, so TRT keeps its
  /// Lambda per phase and tau- follows tau+). Without this call the lattice has one phase and its kernels run the
  /// single-phase code bit for bit. Phase 1 stays empty until set_inner_nodes().
  void set_inner_collision(const CollisionParams& inner);
  /// Makes exactly `nodes` (local linear indices, layout().index(); nodes that are not fluid are skipped) the phase-1
  /// nodes and splits the runs where the phase changes, so that each run relaxes with one set of rates.
  /// pre: initialize() and set_inner_collision() done. Not collective: each rank marks its own nodes.
  void set_inner_nodes(std::span<const std::ptrdiff_t> nodes);
  [[nodiscard]] bool two_phases() const { return inner_collision_.has_value(); }
  [[nodiscard]] const CollisionParams& inner_collision() const { return inner_collision_ ? *inner_collision_ : spec_.collision; }
  /// Phase-1 nodes of this rank.
  [[nodiscard]] std::size_t inner_node_count() const { return inner_nodes_.size(); }
  [[nodiscard]] bool is_inner(int x, int y, int z) const {
    return !phase_.empty() && phase_[static_cast<std::size_t>(layout_.index(x, y, z))] != 0;
  }
  /// Relaxation time tau+ of a local interior node: its phase's.
  [[nodiscard]] double tau_at(int x, int y, int z) const {
    return is_inner(x, y, z) ? inner_collision_->tau : spec_.collision.tau;
  }

  // ---- time stepping ----
  /// One step = stream_collide(); exchange_halos(); apply_boundaries(). Collective.
  void step();
  /// Stage 1: fused pull-stream + collision on every fluid node (uses the force field as it is now).
  void stream_collide();
  /// Stage 2: ghost-layer exchange of the new post-collision populations. Collective.
  void exchange_halos();
  /// Stage 3: open-boundary and wall passes; afterwards the state is complete (moments() etc. are valid).
  void apply_boundaries();
  void run(long steps);
  [[nodiscard]] long steps_done() const { return steps_; }

  // ---- access (local interior nodes) ----
  [[nodiscard]] const common::CartesianDecomposition& decomposition() const { return *decomposition_; }
  [[nodiscard]] const common::BlockLayout& layout() const { return layout_; }
  [[nodiscard]] const CollisionParams& collision() const { return spec_.collision; }
  [[nodiscard]] Streaming streaming() const { return spec_.streaming; }
  [[nodiscard]] std::array<int, 3> offset() const { return decomposition_->offset(); }
  [[nodiscard]] bool is_fluid(int x, int y, int z) const { return flags_[static_cast<std::size_t>(layout_.index(x, y, z))] == kFluid; }
  /// Pre-collision population f_i at a local interior node (ghost nodes are not valid arguments).
  [[nodiscard]] double population(int x, int y, int z, int i) const;
  [[nodiscard]] Populations populations(int x, int y, int z) const;
  /// Force density acting at a node this step (body force + force field).
  [[nodiscard]] common::Vec3 force(int x, int y, int z) const;
  /// rho and the half-force velocity u = (sum f c + F/2)/rho at a node.
  [[nodiscard]] NodeMoments moments(int x, int y, int z) const;
  /// Viscous stress with the forcing correction (see resolved::viscous_stress), lattice units.
  [[nodiscard]] SymTensor viscous_stress(int x, int y, int z) const;
  /// Per-node force density field, SoA (3 components, stride layout().volume(), index layout().index()).
  /// Empty unless enable_force_field(). The IBM adds to it and clears it each step.
  [[nodiscard]] std::span<double> force_field() { return force_field_; }
  void add_force(int x, int y, int z, const common::Vec3& f_lu);
  void clear_force_field();

  /// Fills interior fields, x fastest: rho (solid nodes: rho0) and u (xyz interleaved; solid nodes: 0).
  void macroscopic(std::vector<double>& rho, std::vector<double>& u_xyz) const;
  /// Total mass of the fluid nodes over all ranks. Collective.
  [[nodiscard]] double total_mass() const;
  /// Watchdog: throws hs::common::NumericalError naming the global node, the value and the limit on NaN,
  /// density outside [rho_min, rho_max] or Mach > mach_max at any fluid node of any rank. Collective.
  void check_health(const HealthLimits& limits = {}) const;
  /// Checkpoints: the complete state between steps is the current population buffer (interior, ghosts and wall
  /// slots) plus the step count (whose parity gives the AA layout; restore only what the same scheme wrote). restore_raw_populations() takes what raw_populations() gave on the same lattice
  /// (same spec and decomposition, after initialize()); throws std::invalid_argument on a size mismatch.
  [[nodiscard]] std::span<const double> raw_populations() const { return {src_.data(), src_.size()}; }
  void restore_raw_populations(std::span<const double> f, long steps);
  /// Number of boundary links (diagnostics).
  [[nodiscard]] std::size_t wall_link_count() const { return links_.size(); }

 private:
  static constexpr unsigned char kFluid = 0;
  static constexpr unsigned char kShapeSolid = 1;
  static constexpr unsigned char kFaceSolid = 2;
  static constexpr unsigned char kOpen = 3;
  struct OpenFace {
    bool velocity_given = false;
    std::function<common::Vec3(const common::Vec3&)> profile;
    double rho_lu = 1.0;
  };

  [[nodiscard]] bool streaming_stores() const;
  [[nodiscard]] bool aa() const { return spec_.streaming == Streaming::aa; }
  /// The body force for the wall links' Lambda shift (boundary_links.hpp), nullptr when the closures have none.
  [[nodiscard]] const common::Vec3* link_body_force() const {
    return spec_.collision.model == CollisionModel::regularized ? &body_force_ : nullptr;
  }
  /// AA only: the layout of the buffer now (natural after an odd number of steps).
  [[nodiscard]] AaLayout aa_layout() const;
  [[nodiscard]] std::ptrdiff_t aa_wrap_x() const;
  void aa_stream_collide();
  void aa_exchange();
  [[nodiscard]] unsigned char classify(const std::array<int, 3>& global) const;
  [[nodiscard]] common::Vec3 shape_point(const std::array<int, 3>& global) const;
  void classify_nodes();
  void build_runs();
  void build_wall_links();
  void build_open_nodes();
  void build_aa_layers();
  void build_odd_part_runs();
  [[nodiscard]] std::array<const double*, D3Q19::q> population_table() const;
  void complete_state();
  [[nodiscard]] std::array<int, 3> global_of(std::ptrdiff_t index) const;
  [[nodiscard]] std::ptrdiff_t index(int x, int y, int z) const { return layout_.index(x, y, z); }
  /// AA: layer_runs_ from runs_ (the runs are in z-major order).
  void index_layer_runs();
  /// The kernels' `inner` argument: nullptr with one phase.
  [[nodiscard]] const PhaseRelaxation* inner_relaxation() const { return inner_collision_ ? &inner_relaxation_ : nullptr; }

  LatticeSpec spec_;
  std::unique_ptr<common::CartesianDecomposition> decomposition_;
  common::BlockLayout layout_;
  std::unique_ptr<common::HaloExchange> halo_;
  std::array<std::ptrdiff_t, D3Q19::q> offsets_{};
  const common::Shape* shape_ = nullptr;
  ShapePlacement placement_;
  WallRule wall_rule_ = WallRule::half_way;
  std::array<std::array<common::Vec3, 2>, 3> face_wall_velocity_{};
  std::array<std::array<std::optional<OpenFace>, 2>, 3> open_faces_{};
  common::Vec3 body_force_;
  std::size_t stride_ = 0;   // component stride of the populations: volume() rounded up to whole cache lines
  AlignedDoubles src_, dst_;
  std::vector<double> force_field_;
  std::vector<unsigned char> flags_;
  std::vector<FluidRun> runs_;
  std::size_t fluid_nodes_ = 0;
  std::vector<WallLink> links_;
  /// AA: links_ resolved for the swapped layout [0] (steps_done() even) and the natural one [1] (steps_done() odd).
  std::array<std::vector<AaWallLink>, 2> aa_links_;
  /// AA: the pre-collision odd parts of the nodes with Bouzidi links, kept by the kernel (AaStreamCollideArgs::odd_parts):
  /// odd_part_nodes_ entries per pair.
  std::vector<double> link_odd_parts_;
  std::size_t odd_part_nodes_ = 0;
  /// AA: links_[0, fused_links_) are those at least two nodes from every block face, z-major; the kernel captures and
  /// applies them layer by layer while the layer is in cache: layer z's links_[layer_links_[2z], layer_links_[2z + 1]) once
  /// layers z - 1 and z are updated, links_[layer_links_[2z + 1], layer_links_[2z + 2]) once z and z + 1 are.
  /// The others need the ghost passes and follow them in apply_boundaries().
  std::size_t fused_links_ = 0;
  std::vector<std::size_t> layer_links_;
  std::vector<std::size_t> layer_runs_;   // AA: runs_[layer_runs_[z], layer_runs_[z + 1]) lie in local layer z
  bool fused_links_done_ = false;         // the last aa_stream_collide() applied the fused links
  bool links_need_odd_parts_ = false;    // some link has e != 0 (Bouzidi)
  std::unique_ptr<AaHalo> aa_halo_;      // AA: ghost fill before neighbour steps, fold after them
  std::vector<OpenNode> open_nodes_;
  std::array<std::array<std::vector<int>, 2>, 3> halo_components_;
  bool reduced_halo_ = true;
  long steps_ = 0;
  // Two phases (set_inner_collision): the inner relaxation, the phase of every node (1 = inner; empty until
  // set_inner_nodes), the inner nodes, and the runs as initialize() built them, before the split by phase.
  std::optional<CollisionParams> inner_collision_;
  PhaseRelaxation inner_relaxation_{};
  std::vector<std::uint8_t> phase_;
  std::vector<std::ptrdiff_t> inner_nodes_;
  std::vector<FluidRun> geometry_runs_;
};

}  // namespace hs::resolved
