// SPDX-License-Identifier: MIT
// The single list of case types `hemoscale run` knows: one line per case.
#include "app/registry.hpp"
#include "resolved/cases/plate_cell.hpp"
#include "resolved/cases/shear_suspension.hpp"
#include "resolved/cases/stenosis_cell.hpp"
#include "resolved/cases/stretching.hpp"
#include "resolved/cases/tube_cell.hpp"
#include "resolved/cases/tube_poiseuille.hpp"
#include "unresolved/cases/open_geometry.hpp"
#include "unresolved/cases/tube_open.hpp"
#include "unresolved/cases/tube_plasma.hpp"
#include "unresolved/cases/tube_pries.hpp"

namespace hs::app {

std::map<std::string, Entry> case_types() {
  std::map<std::string, Entry> r;
  r["tube-poiseuille"] = {"plasma in a periodic tube, checked against Poiseuille", hs::resolved::run_tube_poiseuille};
  r["stretching"] = {"optical-tweezers stretching of one RBC membrane vs Mills et al. 2004", hs::resolved::run_stretching};
  r["tube-plasma"] = {"plasma alone in a periodic tube (unresolved FVM), checked against Poiseuille", hs::unresolved::run_tube_plasma};
  r["tube-cell"] = {"one RBC in the periodic campaign tube: drag (centre fixed) or lift (axial motion only)", hs::resolved::run_tube_cell};
  r["tube-pries"] = {"RBC spheres in plasma in a periodic tube (CFD-DEM): Ht_d and mu_rel vs Pries 1992", hs::unresolved::run_tube_pries};
  r["tube-open"] = {"RBC spheres injected at the inlet of an open tube, removed at its outlet (CFD-DEM): Ht_d in and out, Fahraeus", hs::unresolved::run_tube_open};
  r["open-geometry"] = {"RBC spheres through any geometry (tube, stenosis, bifurcation, box, STL) between named openings (CFD-DEM)", hs::unresolved::run_open_geometry};
  r["shear"] = {"one RBC in simple shear between moving plates: flow mode, tumbling period vs Jeffery, inclination", hs::resolved::run_shear};
  r["migration"] = {"one RBC released off-centre in plane Poiseuille flow: lateral migration (Shi et al. 2014)", hs::resolved::run_migration};
  r["shear-suspension"] = {"many RBCs at a hematocrit in simple shear between moving plates: relative viscosity from the stresslets", hs::resolved::run_shear_suspension};
  r["stenosis"] = {"one RBC through a planar stenosed channel: D_x, D_y, D_z through the throat (Hsieh 2020)", hs::resolved::run_stenosis};
  return r;
}

}  // namespace hs::app
