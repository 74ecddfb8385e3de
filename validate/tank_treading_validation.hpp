// SPDX-License-Identifier: MIT
// `hemoscale validate tank-treading`: the resolved cell's tank-treading frequency vs Fischer & Korzeniewski 2015.
#pragma once

#include "common/case_request.hpp"

namespace hs::resolved {
int validate_tank_treading(const hs::common::TaskOptions& options);
}  // namespace hs::resolved
