// SPDX-License-Identifier: MIT
#include "unresolved/cases/grid_budget.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "common/memory_budget.hpp"

namespace hs::unresolved {

void require_tube_grid_memory(const hs::common::ConfigFile& file, double diameter_m, double length_m, int cells_across,
                              double particles) {
  const double along = std::ceil(length_m / (diameter_m / cells_across));
  const double cells = static_cast<double>(cells_across) * cells_across * along;
  const std::array<hs::common::SizingKey, 3> keys{
      {{"[geometry] diameter_m", diameter_m, true},
       {"[geometry] length_m", length_m, true},
       {"[numerics] cells_across_diameter", static_cast<double>(cells_across), false}}};
  std::string what = fmt::format("a grid of {} x {} x {:.0f} cells", cells_across, cells_across, along);
  if (particles > 0.0) what += fmt::format(" and ~{:.3g} particles", particles);
  hs::common::require_memory(file, {what, cells * kFvmBytesPerCell + particles * kDemBytesPerParticle}, keys);
}

void require_box_grid_memory(const hs::common::ConfigFile& file, const hs::common::Box3& box, double dx_m, double particles) {
  std::array<double, 3> n{};
  double largest = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double side = box.hi[a] - box.lo[a];
    n[static_cast<std::size_t>(a)] = std::ceil(side / dx_m);
    largest = std::max(largest, side);
  }
  const std::array<hs::common::SizingKey, 2> keys{
      {{"[numerics] dx_m", dx_m, true}, {"the domain box's longest side", largest, true}}};
  std::string what = fmt::format("a grid of {:.0f} x {:.0f} x {:.0f} cells", n[0], n[1], n[2]);
  if (particles > 0.0) what += fmt::format(" and ~{:.3g} particles", particles);
  hs::common::require_memory(file, {what, n[0] * n[1] * n[2] * kFvmBytesPerCell + particles * kDemBytesPerParticle}, keys);
}

}  // namespace hs::unresolved
