// SPDX-License-Identifier: MIT
// Ghost-layer exchange of structure-of-arrays fields on a Cartesian block decomposition.
#pragma once

#include <span>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"

namespace hs::common {

/// Fills the ghost layers of a field laid out as in BlockLayout (component c at c * volume()) from the
/// neighbouring ranks, axis by axis (x, then y including x ghosts, then z including x and y ghosts), so
/// edge and corner ghosts are filled too. Along a periodic axis with one rank the block exchanges with
/// itself through MPI like any other neighbour, so np = 1 runs the very same code path. Ghosts on a
/// non-periodic global face are left untouched (boundary conditions own them).
class HaloExchange {
 public:
  explicit HaloExchange(const CartesianDecomposition& decomposition);

  /// Exchanges every component of `field` (component c at c * stride; stride 0 means volume()). Collective.
  void exchange(std::span<double> field, int components, std::size_t stride = 0);
  /// Exchanges only the listed components; `per_face[axis][side]` lists the components sent through that
  /// face (e.g. only the populations that leave the block there). Collective.
  void exchange(std::span<double> field, const std::array<std::array<std::vector<int>, 2>, 3>& per_face,
                std::size_t stride = 0);

 private:
  void exchange_axis(std::span<double> field, int axis, const std::vector<int>& to_low,
                     const std::vector<int>& to_high);
  void pack(std::span<const double> field, int axis, int first, const std::vector<int>& comps,
            std::vector<double>& buf) const;
  void unpack(std::span<double> field, int axis, int first, const std::vector<int>& comps,
              const std::vector<double>& buf) const;

  std::size_t stride_ = 0;   // component stride of the field being exchanged

  const CartesianDecomposition& decomposition_;
  std::vector<double> send_low_, send_high_, recv_low_, recv_high_;
};

}  // namespace hs::common
