// SPDX-License-Identifier: MIT
// Node-local formulas: equilibrium, moments with the Guo half-force velocity, viscous stress.
#pragma once

#include <array>

#include "common/vec3.hpp"
#include "resolved/lbm/d3q19.hpp"

namespace hs::resolved {

using Populations = std::array<double, D3Q19::q>;

/// Second-order equilibrium f_i^eq = w_i rho [1 + 3 c.u + 9/2 (c.u)^2 - 3/2 u.u] (Krueger et al. 2017, eq. 3.54).
inline double equilibrium(int i, double rho, const common::Vec3& u) {
  const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
  const double cu = c[0] * u.x + c[1] * u.y + c[2] * u.z;
  return D3Q19::w[static_cast<std::size_t>(i)] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * dot(u, u));
}

struct NodeMoments {
  double rho = 1.0;
  common::Vec3 u;   // half-force velocity (sum f c + F/2) / rho
};

/// rho = sum f_i; u = (sum f_i c_i + F/2) / rho (Guo, Zheng & Shi 2002, Phys. Rev. E 65:046308).
/// pre: `f` are pre-collision populations, `force` the force density acting at this node this step.
inline NodeMoments moments(const Populations& f, const common::Vec3& force) {
  NodeMoments m;
  m.rho = 0.0;
  common::Vec3 j;
  for (int i = 0; i < D3Q19::q; ++i) {
    const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
    const double fi = f[static_cast<std::size_t>(i)];
    m.rho += fi;
    j += common::Vec3{fi * c[0], fi * c[1], fi * c[2]};
  }
  m.u = (j + 0.5 * force) / m.rho;
  return m;
}

/// Symmetric 3x3 tensor stored as xx, yy, zz, xy, xz, yz.
using SymTensor = std::array<double, 6>;

/// Deviatoric (viscous) stress from the non-equilibrium populations with the Guo forcing correction:
/// sigma'_ab = -(1 - 1/(2 tau)) [ Pi^neq_ab + (u_a F_b + F_a u_b)/2 ],  Pi^neq_ab = sum_i (f_i - f_i^eq) c_ia c_ib,
/// with f^eq and u the half-force equilibrium and velocity (Krueger et al. 2017, sections 6.3.2 and 7.2.3;
/// the F-term follows from the Chapman-Enskog expansion with the Guo source term). tau is tau+ for TRT.
/// Lattice units (rho dx^2/dt^2). pre: `f` pre-collision populations, `force` this node's force density.
inline SymTensor viscous_stress(const Populations& f, const common::Vec3& force, double tau) {
  const NodeMoments m = moments(f, force);
  SymTensor pi{};
  constexpr std::array<std::array<int, 2>, 6> ab{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  for (int i = 0; i < D3Q19::q; ++i) {
    const double fneq = f[static_cast<std::size_t>(i)] - equilibrium(i, m.rho, m.u);
    const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < 6; ++k) pi[k] += fneq * c[static_cast<std::size_t>(ab[k][0])] * c[static_cast<std::size_t>(ab[k][1])];
  }
  SymTensor s{};
  const double factor = -(1.0 - 0.5 / tau);
  for (std::size_t k = 0; k < 6; ++k) {
    const int a = ab[k][0];
    const int b = ab[k][1];
    s[k] = factor * (pi[k] + 0.5 * (m.u[a] * force[b] + force[a] * m.u[b]));
  }
  return s;
}

}  // namespace hs::resolved
