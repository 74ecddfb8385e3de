// SPDX-License-Identifier: MIT
// The single list of validations `hemoscale validate NAME` runs: one line per validation.
#include "app/registry.hpp"
#include "validate/capsule_validation.hpp"
#include "validate/lift_transfer_validation.hpp"
#include "validate/pries_validation.hpp"
#include "validate/resolved_dataset_validation.hpp"
#include "validate/stretching_validation.hpp"
#include "validate/tank_treading_validation.hpp"
#include "validate/tumbling_threshold_validation.hpp"


namespace hs::app {

std::map<std::string, TaskEntry> validations() {
  std::map<std::string, TaskEntry> r;
  r["stretching"] = {"RBC optical-tweezers stretching vs Mills et al. 2004 (13 forces, 258 + 642 vertices)", hs::resolved::validate_stretching};
  r["pries"] = {"Fahraeus-Lindqvist tube table (CFD-DEM) vs Pries et al. 1992 (learned closures, bulk viscosity; --closures NAME|FILE|DIR, --suspension-viscosity)", hs::unresolved::validate_pries};
  r["pries-wall"] = {"the pries table (same model and options) with the Haberman-Sayre wall correction of the drag", hs::unresolved::validate_pries_wall};
  r["pries-wall-relative"] = {"the pries table with the Haberman-Sayre factor relative to the learned closures' 50 um tube", hs::unresolved::validate_pries_wall_relative};
  r["lift-transfer"] = {"the learned lift closure (R_c = 25 um) vs resolved runs at R_c = 15 um (data/resolved/transfer-r15; --closures FILE)", hs::closures::validate_lift_transfer};
  r["resolved-dataset"] = {"the campaign's data/resolved/dataset.csv: every (Re, r*) row, the acceptance rules, ranges vs the seed paper", hs::campaign::validate_resolved_dataset};
  r["tank-treading"] = {"one RBC's tank-treading frequency in shear vs Fischer & Korzeniewski 2015 (data/resolved-shear/fischer-korzeniewski; its campaign)", hs::resolved::validate_tank_treading};
  r["capsule"] = {"a neo-Hookean capsule's steady Taylor deformation in shear vs Ramanujan & Pozrikidis 1998 and Doddi & Bagchi 2008 (data/resolved-shear/capsule; its campaign)", hs::resolved::validate_capsule};
  r["tumbling-threshold"] = {"one RBC's tumbling to tank-treading transition in shear vs Fischer & Korzeniewski 2013 (data/resolved-shear/threshold-23.9; its campaign)", hs::resolved::validate_tumbling_threshold};
  return r;
}

}  // namespace hs::app
