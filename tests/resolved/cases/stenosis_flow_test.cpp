// SPDX-License-Identifier: MIT
// Plasma alone in the periodic stenosed channel of the `stenosis` case: the straight-channel limit against plane
// Poiseuille flow, continuity through the 5.5 um stenosis (the lattice's mass flux through every face; the reported
// nodal flow rate within its quadrature bound), and the lubrication estimate of the drive against its closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

#include "common/config/config_file.hpp"
#include "common/units/unit_converter.hpp"
#include "resolved/cases/case_text_helpers.hpp"
#include "resolved/cases/stenosis_cell_config.hpp"
#include "resolved/cases/stenosis_flow.hpp"

namespace hs::resolved {
namespace {

std::string shipped(const std::string& folder) { return test::shipped_case_text(folder); }

std::string with(const std::string& text, const std::string& from, const std::string& to) {
  return test::replaced(text, from, to);
}

/// The shipped 5.5 um case, 10 um wide (the plasma flow does not depend on z), with `throat` as the throat line and
/// the wall rule `wall` ("bouzidi", the default, or "half_way").
StenosisCellConfig plasma_case(const std::string& throat, const std::string& wall = "bouzidi") {
  std::string toml = with(shipped("stenosis/throat-5.5um"), "width_m = 16.0e-6", "width_m = 10.0e-6");
  toml = with(toml, "throat_height_m = 5.5e-6", throat);
  toml = with(toml, "max_tau = 12.5", "max_tau = 12.5\nwall = \"" + wall + "\"");
  auto file = common::ConfigFile::parse(toml, "case.toml");
  EXPECT_EQ(file->root().section("case").string("type"), "stenosis");
  return read_stenosis_cell(*file, false);
}

common::UnitConverter units_of(const StenosisCellConfig& c) {
  return common::UnitConverter(
      common::LatticeScales{.dx_m = c.numerics.dx_m, .dt_s = c.numerics.dt_s, .rho_kg_m3 = c.density_kg_m3});
}

TEST(StenosisPlasma, NearlyStraightChannelCarriesThePoiseuilleFlowRate) {
  // Throat 14.99 um of 15: lubrication gives g = 12 nu q / H^3 to 1e-3, and the straight walls lie half-way between
  // nodes, where TRT with the magic parameter 3/16 makes half-way bounce-back exact for plane Poiseuille flow.
  const StenosisCellConfig c = plasma_case("throat_height_m = 14.99e-6");
  const auto units = units_of(c);
  const double q = c.flow_rate_m2_s();
  const double g = 12.0 * c.kinematic_viscosity_m2_s * q / (c.height_m * c.height_m * c.height_m);
  const PlasmaFlow flow = steady_plasma_flow(c, units, g, 1e-7, 100000);
  // 0.5 %: the 0.01 um constriction (<= 0.3 % more resistance over 1/3 of the box) plus the steady-state tolerance.
  EXPECT_NEAR(flow.mean_flow_rate_m2_s / q, 1.0, 5e-3);
}

TEST(StenosisPlasma, MassFluxIsTheSameThroughEveryFace) {
  // Half-way bounce-back conserves mass link by link, so at steady state the lattice's own mass flux through every
  // face between x-planes must be the same: this checks that the constricted channel is closed and the run steady.
  // (The interpolated Bouzidi rule moves mass between neighbouring nodes along wall links, so its face fluxes alone do
  // not balance: measured 3 % lower at the throat, with the mass carried by the wall links.)
  const StenosisCellConfig c = plasma_case("throat_height_m = 5.5e-6", "half_way");
  const PlasmaFlow flow = steady_plasma_flow(c, units_of(c), lubrication_drive_m_s2(c, c.flow_rate_m2_s()), 1e-7, 100000);
  const auto faces = static_cast<std::size_t>(std::lround(c.length_m / c.numerics.dx_m));   // periodic: one per x-plane
  ASSERT_EQ(flow.face_mass_fluxes_lu.size(), faces);
  const auto [lo, hi] = std::minmax_element(flow.face_mass_fluxes_lu.begin(), flow.face_mass_fluxes_lu.end());
  const double mean =
      std::accumulate(flow.face_mass_fluxes_lu.begin(), flow.face_mass_fluxes_lu.end(), 0.0) / static_cast<double>(faces);
  // 1e-4: once the mean flow rate is steady (< 1e-7 change per viscous time) weakly damped pressure waves still slosh
  // along x and move mass between slabs (measured spread 3.3e-5); a leak at the walls would show at the 1e-2 level.
  EXPECT_LT((*hi - *lo) / mean, 1e-4);
}

TEST(StenosisPlasma, NodalFlowRateIsContinuousUpToTheWallQuadrature) {
  // The flow rate the case reports sums rho u_x over the nodes of a plane. Where a wall cuts between nodes the sum is
  // a quadrature of the near-wall profile with error up to ~2 (dx / h)^2 of the flow rate (Euler-Maclaurin end terms
  // for a parabola): 6.6 % at the 5.5 um throat with dx = 1 um. Continuity must hold to within that bound.
  for (const std::string wall : {"bouzidi", "half_way"}) {
    const StenosisCellConfig c = plasma_case("throat_height_m = 5.5e-6", wall);
    const PlasmaFlow flow = steady_plasma_flow(c, units_of(c), lubrication_drive_m_s2(c, c.flow_rate_m2_s()), 1e-7, 100000);
    const auto [lo, hi] = std::minmax_element(flow.plane_flow_rates_m2_s.begin(), flow.plane_flow_rates_m2_s.end());
    EXPECT_LT((*hi - *lo) / flow.mean_flow_rate_m2_s, 2.0 * std::pow(c.numerics.dx_m / c.throat_height_m, 2)) << wall;
    if (wall != "bouzidi") continue;
    // Lubrication neglects the wall slope (up to 0.75 here), which adds resistance: the lubrication drive gives less
    // than the target flow rate (measured 0.86 of it with Bouzidi walls at dx = 1 um; the case corrects the drive).
    EXPECT_LT(flow.mean_flow_rate_m2_s, c.flow_rate_m2_s());
    EXPECT_GT(flow.mean_flow_rate_m2_s, 0.8 * c.flow_rate_m2_s());
  }
}

TEST(StenosisPlasma, LubricationDriveMatchesTheClosedForm) {
  const StenosisCellConfig c = plasma_case("throat_height_m = 5.5e-6");
  // h = A - B cos(2 pi s / L_c) over the constriction, A = (H + h_t) / 2, B = (H - h_t) / 2, and
  // int_0^{2 pi} dt / (A - B cos t)^3 = pi (2 A^2 + B^2) / (A^2 - B^2)^{5/2} with A^2 - B^2 = H h_t (Gradshteyn 2.554),
  // so int dx / h^3 = (L - L_c) / H^3 + L_c (2 A^2 + B^2) / (2 (H h_t)^{5/2}).
  const double big_h = c.height_m, h_t = c.throat_height_m, l_c = c.constriction_length_m, q = 1e-9;
  const double a = 0.5 * (big_h + h_t), b = 0.5 * (big_h - h_t);
  const double integral = (c.length_m - l_c) / (big_h * big_h * big_h) +
                          l_c * (2.0 * a * a + b * b) / (2.0 * std::pow(big_h * h_t, 2.5));
  const double expected = 12.0 * c.kinematic_viscosity_m2_s * q * integral / c.length_m;
  // 1e-8: the midpoint rule on 20000 points of a smooth periodic integrand converges much faster than 1/n^2.
  EXPECT_NEAR(lubrication_drive_m_s2(c, q) / expected, 1.0, 1e-8);
}

}  // namespace
}  // namespace hs::resolved
