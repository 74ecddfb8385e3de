// SPDX-License-Identifier: MIT
// The plasma flow of the periodic stenosed channel: lattice, lubrication drive, plane flow rates, steady plasma run.
#include "resolved/cases/stenosis_flow.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <mpi.h>

#include "common/geometry/constriction_profile.hpp"
#include "common/geometry/stenosed_channel.hpp"
#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {
namespace {

/// Midpoint-rule points of the lubrication integral: the integrand is smooth (C1), error ~1e-9 relative.
constexpr int kLubricationPoints = 20000;
/// Solid nodes kept beyond each straight wall (the shape's wall links need a solid node; two as in the tube case).
constexpr int kSolidLayers = 2;

}  // namespace

StenosisGrid stenosis_grid(const StenosisCellConfig& c) {
  const double dx = c.numerics.dx_m;
  const int ny = static_cast<int>(std::lround(c.height_m / dx)) + 2 * kSolidLayers + 1;
  return {.nodes = {static_cast<int>(std::lround(c.length_m / dx)), ny, static_cast<int>(std::lround(c.width_m / dx))},
          .origin_m = {0.0, -(kSolidLayers + 0.5) * dx, 0.0}};
}

std::unique_ptr<FluidLattice> make_stenosis_lattice(const StenosisCellConfig& c, const StenosisGrid& grid) {
  auto lattice = std::make_unique<FluidLattice>(
      LatticeSpec{.global_nodes = grid.nodes, .periodic = {true, false, true}, .collision = c.numerics.collision,
                  .streaming = c.numerics.streaming},
      MPI_COMM_WORLD);
  const common::StenosedChannel channel(c.channel());   // used by initialize() only
  lattice->set_shape(channel, ShapePlacement{.origin = grid.origin_m, .spacing = c.numerics.dx_m}, c.numerics.wall);
  lattice->enable_force_field();
  lattice->initialize();
  return lattice;
}

double lubrication_drive_m_s2(const StenosisCellConfig& c, double flow_rate_m2_s) {
  const common::ConstrictionProfile profile{0.5 * c.height_m, 0.5 * c.throat_height_m, c.constriction_length_m};
  const double step = c.length_m / kLubricationPoints;
  double integral = 0.0;
  for (int i = 0; i < kLubricationPoints; ++i) {
    const double x = (i + 0.5) * step;
    const double h = 2.0 * profile.half_width(x - c.throat_x_m);
    integral += step / (h * h * h);
  }
  return 12.0 * c.kinematic_viscosity_m2_s * flow_rate_m2_s * integral / c.length_m;
}

std::vector<double> plane_flow_rates_m2_s(const FluidLattice& lattice, const common::UnitConverter& units,
                                          double width_m) {
  const auto& n = lattice.layout().n;
  const int x0 = lattice.offset()[0];
  std::vector<double> flux(static_cast<std::size_t>(lattice.decomposition().global_nodes()[0]), 0.0);
  for (int z = 0; z < n[2]; ++z) {
    for (int y = 0; y < n[1]; ++y) {
      for (int x = 0; x < n[0]; ++x) {
        if (!lattice.is_fluid(x, y, z)) continue;
        const NodeMoments m = lattice.moments(x, y, z);
        flux[static_cast<std::size_t>(x0 + x)] += m.rho * m.u.x;
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, flux.data(), static_cast<int>(flux.size()), MPI_DOUBLE, MPI_SUM,
                lattice.decomposition().comm());
  // Mass flux (lattice units, rho0 = 1) through the plane of nodes: volume flux in dx^3 / dt.
  const double dx = units.dx_m();
  for (double& q : flux) q = q * dx * dx * dx / units.dt_s() / width_m;
  return flux;
}

std::vector<double> face_mass_fluxes_lu(const FluidLattice& lattice) {
  if (lattice.decomposition().size() != 1) throw std::logic_error("face_mass_fluxes_lu: one rank only");
  const auto& n = lattice.layout().n;
  const auto fluid = [&](int x, int y, int z) {
    return y >= 0 && y < n[1] && lattice.is_fluid((x + n[0]) % n[0], y, (z + n[2]) % n[2]);
  };
  std::vector<double> flux(static_cast<std::size_t>(n[0]), 0.0);
  for (int x = 0; x < n[0]; ++x) {
    const int xp = (x + 1) % n[0];
    for (int z = 0; z < n[2]; ++z) {
      for (int y = 0; y < n[1]; ++y) {
        for (int i = 1; i < D3Q19::q; ++i) {
          const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
          if (c[0] == 0) continue;
          // Destination node on the far side of the face; its pre-collision f_i came from destination - c_i.
          const int xd = c[0] > 0 ? xp : x;
          if (!fluid(xd, y, z) || !fluid(xd - c[0], y - c[1], z - c[2])) continue;
          flux[static_cast<std::size_t>(x)] += c[0] * lattice.population(xd, y, z, i);
        }
      }
    }
  }
  return flux;
}

double mean_flow_rate_m2_s(const FluidLattice& lattice, const common::UnitConverter& units, double width_m) {
  const auto q = plane_flow_rates_m2_s(lattice, units, width_m);
  return std::accumulate(q.begin(), q.end(), 0.0) / static_cast<double>(q.size());
}

PlasmaFlow steady_plasma_flow(const StenosisCellConfig& c, const common::UnitConverter& units, double drive_m_s2,
                              double tolerance, long max_steps) {
  const StenosisGrid grid = stenosis_grid(c);
  auto lattice = make_stenosis_lattice(c, grid);
  lattice->set_body_force({units.to_lattice_acceleration(drive_m_s2), 0.0, 0.0});
  // Checked once per viscous time H^2 / nu (at least 10 steps): the slowest mode decays as exp(-pi^2 nu t / H^2).
  const long block = std::max(10L, units.to_lattice_steps(c.height_m * c.height_m / c.kinematic_viscosity_m2_s));
  PlasmaFlow out;
  out.drive_m_s2 = drive_m_s2;
  double previous = 0.0;
  while (out.steps < max_steps) {
    lattice->run(block);
    out.steps += block;
    lattice->check_health();
    out.mean_flow_rate_m2_s = mean_flow_rate_m2_s(*lattice, units, c.width_m);
    const bool steady = std::abs(out.mean_flow_rate_m2_s - previous) <= tolerance * std::abs(out.mean_flow_rate_m2_s);
    previous = out.mean_flow_rate_m2_s;
    if (steady) break;
  }
  out.plane_flow_rates_m2_s = plane_flow_rates_m2_s(*lattice, units, c.width_m);
  if (lattice->decomposition().size() == 1) out.face_mass_fluxes_lu = face_mass_fluxes_lu(*lattice);
  return out;
}

}  // namespace hs::resolved
