// SPDX-License-Identifier: MIT
// The Cartesian finite-volume grid over a Shape: staggered (MAC) velocity nodes, cut-cell face apertures
// and wall distances along grid links, and the boundary conditions: per side of the domain box, and per named opening.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/geometry/opening_condition.hpp"
#include "common/parallel/cartesian_decomposition.hpp"
#include "common/geometry/shape.hpp"
#include "common/vec3.hpp"
#include "unresolved/fvm/block_field.hpp"
#include "unresolved/fvm/block_halo.hpp"

namespace hs::unresolved {

/// What happens at one side of the domain box. Walls of the Shape inside the box are always no-slip.
enum class SideType : std::uint8_t { periodic, wall, velocity_inlet, pressure_outlet };

struct SideCondition {
  SideType type = SideType::wall;
  hs::common::Vec3 wall_velocity_m_s{};                              // wall: tangential (lid) velocity
  std::function<hs::common::Vec3(const hs::common::Vec3&)> inlet_velocity_m_s;  // velocity_inlet: u(x)
};

/// Openings (`openings`) refine the sides: a face node (the centre of a cell face on the box) belongs to the opening
/// whose disc holds it (lateral distance from the opening's centre <= radius_m) when it is in the fluid (signed
/// distance < 0); every other fluid face node of that side follows the side's condition, which must be `wall`. So a
/// box side holds any number of inlets and outlets, and walls around and between them. Each opening:
///  flow_rate_inlet:      fixed nodes, u_n = U (1 - r^2 / R^2) into the domain (r = lateral distance, R = radius_m),
///                        with U set so that the *discrete* flux sum(aperture dx^2 u_n) over its nodes equals
///                        flow_rate_m3_s to round-off (the cut faces at the rim carry ~0.7% more than the exact
///                        parabola's pi R^2 U at 10 cells across; normalising by the discrete sum removes it);
///  flow_fraction_outlet: the same profile out of the domain, its discrete flux = flow_fraction x the summed inlet
///                        flow rates;
///  pressure_outlet:      active nodes (zero normal gradient of the velocity, and of the tangential velocity across
///                        the face), pressure = pressure_Pa on the face.
/// The tangential velocity at an inlet or flow-fraction outlet is 0, as at a wall. With eps < 1 in the cells next to
/// an opening the fluid volume flux through it is eps times the above (the nodes hold the interstitial velocity).
struct FvmGridSpec {
  hs::common::Box3 box_m;                 // the domain; each extent must be a whole number of cells
  double dx_m;                            // cubic cells
  std::array<SideCondition, 6> sides;     // x-, x+, y-, y+, z-, z+ (a periodic axis is periodic on both sides)
  std::vector<hs::common::OpeningCondition> openings{};   // on wall sides only; checked by check_opening_conditions
};

/// The face nodes of one opening: the velocity nodes of component `axis` on the box face `axis` (`high`: at box_m.hi).
struct OpeningNodes {
  int axis = 0;
  int high = 0;
  std::vector<std::size_t> nodes;         // flat indices into the component's BlockFields
};

/// Kind of a velocity node (the centre of a cell face, normal component only).
enum class NodeKind : std::uint8_t { solid, active, fixed };

/// How an active velocity node sees one of its six neighbours.
struct NodeLink {
  enum class Type : std::uint8_t { active, dirichlet, neumann } type = Type::active;
  double theta = 1.0;   // dirichlet: fraction of the link (in (0, 1]) at which the wall value holds
  double value = 0.0;   // dirichlet: the wall (or boundary) velocity component, m/s
};

/// Why staggered (MAC): on a Cartesian grid the staggered arrangement couples pressure and velocity
/// without Rhie-Chow interpolation (no checkerboard modes, exact discrete divergence), the face velocity
/// is itself the flux unknown that the cut-cell apertures multiply, and PISO reduces to a 7-point
/// pressure Laplacian that algebraic multigrid solves in a few iterations.
///
/// Walls: a velocity node is active when its face centre lies in the fluid. The viscous stencil of a node
/// next to a wall uses the true wall position along each grid link (Shortley & Weller 1938 non-uniform
/// three-point stencil; the same idea as the ghost-cell method of Gibou et al. 2002, J Comput Phys
/// 176:205), and the flux through a cut face is its
/// open area times the velocity at the centroid of the open part, reconstructed linearly from the wall
/// (aperture(c, ...) below). Both are second order where a staircase wall is first order.
class FvmGrid {
 public:
  /// `slabs`: this rank holds one block of `slabs`, a decomposition of the grid's cells split along z only
  /// (the distributed FVM, docs/cfd-dem.md "Distributed CFD-DEM"): cells() and every field are the block's, with
  /// the neighbouring blocks' planes in the ghost layer along z; a face node on a plane between two blocks belongs
  /// to the block above. nullptr: the whole grid on this rank.
  FvmGrid(const hs::common::Shape& shape, const FvmGridSpec& spec,
          const hs::common::CartesianDecomposition* slabs = nullptr);

  /// The whole grid's cells along each axis; ConfigError when the box is not a whole number of cells.
  [[nodiscard]] static std::array<int, 3> cells_of(const FvmGridSpec& spec);

  [[nodiscard]] double dx_m() const { return dx_m_; }
  [[nodiscard]] const std::array<int, 3>& cells() const { return n_; }
  /// The whole grid's cells and the global index of this block's first plane along z (cells() and 0 without slabs).
  [[nodiscard]] const std::array<int, 3>& global_cells() const { return global_n_; }
  [[nodiscard]] int first_plane() const { return first_plane_; }
  [[nodiscard]] const hs::common::CartesianDecomposition* slabs() const { return slabs_; }
  [[nodiscard]] long cell_count() const { return static_cast<long>(n_[0]) * n_[1] * n_[2]; }
  /// The corner of this block (the box's corner without slabs).
  [[nodiscard]] const hs::common::Vec3& origin_m() const { return lo_; }
  /// The whole domain box (every block's the same).
  [[nodiscard]] const hs::common::Box3& box_m() const { return spec_.box_m; }
  [[nodiscard]] bool periodic(int axis) const { return periodic_[static_cast<std::size_t>(axis)]; }
  [[nodiscard]] const SideCondition& side(int axis, int high) const { return spec_.sides[static_cast<std::size_t>(2 * axis + high)]; }
  [[nodiscard]] const hs::common::Shape& shape() const { return shape_; }
  /// What the grid was built from (every block's the same).
  [[nodiscard]] const FvmGridSpec& spec() const { return spec_; }
  /// The openings of the spec, in its order, and the face nodes each one holds (fvm_grid_openings.cpp).
  [[nodiscard]] const std::vector<hs::common::OpeningCondition>& openings() const { return spec_.openings; }
  [[nodiscard]] const OpeningNodes& opening_nodes(std::size_t k) const { return opening_nodes_[k]; }
  /// The opening on box side (axis, high) whose disc holds x (x on that side's plane), or nullptr.
  [[nodiscard]] const hs::common::OpeningCondition* opening_at(int axis, int high, const hs::common::Vec3& x_m) const;

  /// Number of velocity nodes of component c along axis a (faces along c, cells otherwise; a periodic
  /// axis has its last face identified with the first; a block's last face is the next block's first).
  [[nodiscard]] int node_count(int c, int a) const;
  [[nodiscard]] hs::common::Vec3 cell_centre_m(int i, int j, int k) const;
  [[nodiscard]] hs::common::Vec3 node_position_m(int c, int i, int j, int k) const;
  /// The cell holding x (periodic axes wrapped), or nothing when x is outside the box.
  [[nodiscard]] std::optional<std::array<int, 3>> cell_of(const hs::common::Vec3& x_m) const;
  /// Wraps x into the box along periodic axes; on a block, along z to the image nearest the block (so a point within
  /// the ghost planes across a periodic seam stays there).
  [[nodiscard]] hs::common::Vec3 wrap(const hs::common::Vec3& x_m) const;

  [[nodiscard]] NodeKind kind(int c, int i, int j, int k) const {
    return static_cast<NodeKind>(kind_[static_cast<std::size_t>(c)](i, j, k));
  }
  [[nodiscard]] const BlockField<std::uint8_t>& kinds(int c) const { return kind_[static_cast<std::size_t>(c)]; }
  /// Prescribed value of a fixed node (wall or inlet face on the box), m/s.
  [[nodiscard]] const BlockField<double>& fixed_values(int c) const { return fixed_[static_cast<std::size_t>(c)]; }
  /// Effective aperture of a face (open area fraction x centroid-velocity factor); 0 for solid nodes.
  [[nodiscard]] const BlockField<double>& apertures(int c) const { return aperture_[static_cast<std::size_t>(c)]; }
  /// Open area fraction of each face (geometry only, for diagnostics).
  [[nodiscard]] const BlockField<double>& open_areas(int c) const { return area_[static_cast<std::size_t>(c)]; }
  /// Fluid volume fraction of each cell (geometry only: 1 inside, 0 in the wall, in between when cut).
  [[nodiscard]] const BlockField<double>& fluid_fractions() const { return fluid_fraction_; }
  /// The fluid fraction of any cell of the whole grid by its global index (along z: k + first_plane()), from the shape:
  /// what fluid_fractions() holds for this block's cells, to the bit; for cells of the neighbouring blocks.
  [[nodiscard]] double fluid_fraction_of_cell(int i, int j, int k_global) const;
  /// The link of an active node towards direction dir = 2 a + (0: -a, 1: +a) when that neighbour is not active.
  [[nodiscard]] NodeLink link(int c, std::array<int, 3> node, int dir) const;

 private:
  void classify_nodes(int c);
  void compute_apertures(int c);
  void compute_fluid_fractions();
  void set_up_openings();
  /// Classifies face node (c, i, j, k) at position p when an opening holds it; false otherwise.
  bool classify_opening_node(int c, std::array<int, 3> ijk, const hs::common::Vec3& p);
  void finish_openings();
  [[nodiscard]] bool in_range(int c, int a, int idx) const;
  /// The side of the domain box (0 low, 1 high) that face node index `along` of component c lies on, or -1.
  [[nodiscard]] int box_face(int c, int along) const;
  [[nodiscard]] bool split_along(int a) const { return a == 2 && slabs_ != nullptr; }
  /// Ghost layers: periodic wrap along x and y, the neighbouring blocks' planes (or the periodic wrap) along z.
  template <typename T>
  void fill_ghosts(BlockField<T>& f) const {
    for (int a = 0; a < 3; ++a) {
      if (split_along(a)) {
        exchange_halo(f, *slabs_, a);
      } else if (periodic(a)) {
        f.fill_periodic(a, n_[static_cast<std::size_t>(a)]);
      }
    }
  }

  const hs::common::Shape& shape_;
  FvmGridSpec spec_;
  const hs::common::CartesianDecomposition* slabs_;
  double dx_m_;
  hs::common::Vec3 lo_;                   // this block's origin (the box's without slabs)
  std::array<int, 3> n_{};                // this block's cells
  std::array<int, 3> global_n_{};
  int first_plane_ = 0;
  std::array<bool, 3> periodic_{};
  std::array<BlockField<std::uint8_t>, 3> kind_;
  std::array<BlockField<double>, 3> fixed_;
  std::array<BlockField<double>, 3> aperture_;
  std::array<BlockField<double>, 3> area_;
  BlockField<double> fluid_fraction_;
  std::vector<OpeningNodes> opening_nodes_;
};

/// Fills the ghost layer of a cell-centred field that the coupling sets (Us, f; the solver fills those of eps and
/// Ksl itself): periodic wrap along periodic axes, zero gradient along the others.
template <typename T>
void fill_cell_field_ghosts(const FvmGrid& grid, BlockField<T>& field) {
  for (int a = 0; a < 3; ++a) {
    if (grid.slabs() != nullptr && a == 2) {
      if (grid.slabs()->on_global_face(2, 0) || grid.slabs()->on_global_face(2, 1)) field.fill_zero_gradient(a);
      exchange_halo(field, *grid.slabs(), a);   // the planes between blocks (and the periodic images)
    } else if (grid.periodic(a)) {
      field.fill_periodic(a, grid.cells()[static_cast<std::size_t>(a)]);
    } else {
      field.fill_zero_gradient(a);
    }
  }
}

}  // namespace hs::unresolved
