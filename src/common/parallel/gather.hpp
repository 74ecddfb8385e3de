// SPDX-License-Identifier: MIT
// Collecting a decomposed field on rank 0 (output, tests comparing np = 1 with np = N).
#pragma once

#include <span>
#include <vector>

#include "common/parallel/cartesian_decomposition.hpp"

namespace hs::common {

/// Gathers the interior field of every rank (`components` values per node, interleaved, x fastest over the
/// local block) into the global field on rank 0 (same ordering over the global grid). Other ranks get an
/// empty vector. Collective.
std::vector<double> gather_to_root(const CartesianDecomposition& decomposition, std::span<const double> local,
                                   int components);

}  // namespace hs::common
