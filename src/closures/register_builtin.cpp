// SPDX-License-Identifier: MIT
// The single list of closure models (STYLE R5): one line per model.
#include "closures/register_builtin.hpp"

#include "closures/expression_deformation.hpp"
#include "closures/expression_drag.hpp"
#include "closures/expression_lift.hpp"
#include "closures/named_closure_set.hpp"
#include "closures/saffman_mei_lift.hpp"
#include "closures/schiller_naumann.hpp"
#include "closures/stokes_drag.hpp"

namespace hs::closures {

void register_builtin(DragRegistry& r) {
  r.add("stokes",           [](const ClosureSpec&) { return std::make_unique<StokesDrag>(); });
  r.add("schiller_naumann", [](const ClosureSpec&) { return std::make_unique<SchillerNaumann>(); });
  r.add("expression",       [](const ClosureSpec& s) { return std::make_unique<ExpressionDrag>(s.file, s.outside); });
  for (const auto& set : closure_set_names()) {   // "resolved": the committed set, by name (named_closure_set.hpp)
    r.add(set, [set](const ClosureSpec& s) {
      return std::make_unique<ExpressionDrag>(named_closure_file(set, ClosureKind::drag), s.outside);
    });
  }
}

void register_builtin(LiftRegistry& r) {
  r.add("saffman_mei", [](const ClosureSpec&) { return std::make_unique<SaffmanMeiLift>(); });
  r.add("expression",  [](const ClosureSpec& s) { return std::make_unique<ExpressionLift>(s.file, s.outside); });
  for (const auto& set : closure_set_names()) {
    r.add(set, [set](const ClosureSpec& s) {
      return std::make_unique<ExpressionLift>(named_closure_file(set, ClosureKind::lift), s.outside);
    });
  }
}

void register_builtin(DeformationRegistry& r) {
  r.add("expression", [](const ClosureSpec& s) { return std::make_unique<ExpressionDeformation>(s.file, s.outside); });
  for (const auto& set : closure_set_names()) {
    r.add(set, [set](const ClosureSpec& s) {
      return std::make_unique<ExpressionDeformation>(named_closure_file(set, ClosureKind::deformation), s.outside);
    });
  }
}

std::unique_ptr<DragClosure> make_drag_closure(const ClosureSpec& spec) {
  DragRegistry r;
  register_builtin(r);
  return r.create(spec);
}

std::unique_ptr<LiftClosure> make_lift_closure(const ClosureSpec& spec) {
  LiftRegistry r;
  register_builtin(r);
  return r.create(spec);
}

std::unique_ptr<DeformationClosure> make_deformation_closure(const ClosureSpec& spec) {
  DeformationRegistry r;
  register_builtin(r);
  return r.create(spec);
}

}  // namespace hs::closures
