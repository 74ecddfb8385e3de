// SPDX-License-Identifier: MIT
// The npFEM solver's private working memory: buffers, the blocked proxy solve, the L-BFGS pairs, the start predictor.
#pragma once

#include "resolved/membrane/blocked_ldlt.hpp"
#include "resolved/membrane/lbfgs_memory.hpp"
#include "resolved/membrane/npfem_solver.hpp"

namespace hs::resolved {

/// Allocated once per solver so that a time step allocates nothing (258 vertices: ~25 us per step was new/delete).
struct NpfemSolver::Workspace {
  Workspace(int lbfgs_pairs, int vertices) : history(lbfgs_pairs, vertices) {
    for (Positions* p : {&d, &md, &gt, &xt, &dir, &s, &yk, &rhs, &xn, &u, &gv, &correction[0], &correction[1]}) p->setZero(vertices, 3);
  }
  BlockedLdlt proxy;                 // H0 = M~/h^2 + L, factorised once
  BlockedLdlt damped_mass;           // M~ = M + h beta L, for the inertial predictor y
  LbfgsMemory history;               // kept from step to step
  Positions d, md, gt, xt, dir, s, yk, rhs;
  Positions xn, u, gv;               // membrane viscosity: the step's start, the displacement and its gradient
  Positions correction[2];           // x* - y of the last two steps, newest first
  int corrections = 0;               // how many of them are set (0, 1, 2)
};

}  // namespace hs::resolved
