// SPDX-License-Identifier: MIT
// The single list of studies `hemoscale study NAME` runs: one line per study.
#include "app/registry.hpp"
#include "study/bifurcation_study.hpp"
#include "study/stenosis_study.hpp"

namespace hs::app {

std::map<std::string, StudyEntry> studies() {
  std::map<std::string, StudyEntry> r;
  r["bifurcation"] = {"seed paper 4.3: RBCs through a side branch at 30, 60, 90 deg (S_H, DI histograms, flux split)", hs::study::study_bifurcation};
  r["stenosis"] = {"seed paper 4.4: RBCs through a 150 um tube with 85 and 55 um throats (<DI>(x), Ht(x), hemolysis index)", hs::study::study_stenosis};
  return r;
}

}  // namespace hs::app
