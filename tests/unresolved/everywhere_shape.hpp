// SPDX-License-Identifier: MIT
// A test shape that is fluid everywhere: a fully periodic FVM box has no walls (a BoxShape's own faces would be
// solid nodes, and a periodic face must be open).
#pragma once

#include "common/geometry/shape.hpp"

namespace hs::test {

class Everywhere final : public hs::common::Shape {
 public:
  [[nodiscard]] double signed_distance(const hs::common::Vec3&) const override { return -1.0; }
  [[nodiscard]] hs::common::Box3 bounds() const override { return {{0, 0, 0}, {1, 1, 1}}; }
};

}  // namespace hs::test
