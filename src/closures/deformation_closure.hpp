// SPDX-License-Identifier: MIT
// Interface of deformation closures: the RBC deformation index from the local flow.
#pragma once

#include "closures/closure.hpp"

namespace hs::closures {

/// DI = (L - B) / (L + B) of the cell, from (gamma+, u_r+) in the seed paper.
class DeformationClosure : public Closure {
 public:
  [[nodiscard]] double deformation_index(const DeformationInputs& in) const {
    count(in);
    return compute_deformation_index(in);
  }

 protected:
  using Closure::Closure;
  [[nodiscard]] virtual double compute_deformation_index(const DeformationInputs& in) const = 0;
};

}  // namespace hs::closures
