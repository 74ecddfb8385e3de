// SPDX-License-Identifier: MIT
// Below how many particles a DEM loop runs on one thread.
#pragma once

#include <cstdint>

namespace hs::unresolved {

/// OpenMP regions cost microseconds (milliseconds when a thread is descheduled on a busy machine), more than
/// a loop over a few thousand particles: smaller loops run serially (the `if` clause of each parallel region).
inline constexpr std::int64_t omp_min_particles = 4096;

}  // namespace hs::unresolved
