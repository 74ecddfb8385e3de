// SPDX-License-Identifier: MIT
// The registries of drag, lift and deformation closures, and the one place that fills them.
#pragma once

#include <memory>

#include "closures/closure_registry.hpp"
#include "closures/deformation_closure.hpp"
#include "closures/drag_closure.hpp"
#include "closures/lift_closure.hpp"

namespace hs::closures {

using DragRegistry = ClosureRegistry<DragClosure>;
using LiftRegistry = ClosureRegistry<LiftClosure>;
using DeformationRegistry = ClosureRegistry<DeformationClosure>;

void register_builtin(DragRegistry& r);
void register_builtin(LiftRegistry& r);
void register_builtin(DeformationRegistry& r);

/// Shorthands: a registry filled by register_builtin, then create(spec).
[[nodiscard]] std::unique_ptr<DragClosure> make_drag_closure(const ClosureSpec& spec);
[[nodiscard]] std::unique_ptr<LiftClosure> make_lift_closure(const ClosureSpec& spec);
[[nodiscard]] std::unique_ptr<DeformationClosure> make_deformation_closure(const ClosureSpec& spec);

}  // namespace hs::closures
