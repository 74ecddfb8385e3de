// SPDX-License-Identifier: MIT
// Levenberg-Marquardt constant fitting with Eigen, and closed-form linear scaling.
#include "regression/constant_optimizer.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "regression/compiled_program.hpp"

namespace hs::regression {
namespace {

struct Problem {
  CompiledProgram program;
  const DataView& data;
  std::span<const double> y;
  bool scaled;
  std::size_t k;   // number of tree constants; parameters are c_0..c_{k-1} [, offset, scale]

  // Residuals r = offset + scale * f - y for parameters p; returns false if not finite.
  bool residuals(const Eigen::VectorXd& p, Eigen::VectorXd& f, Eigen::VectorXd& r) {
    program.set_constants(std::span<const double>(p.data(), k));
    program.evaluate(data, std::span<double>(f.data(), data.rows));
    const double offset = scaled ? p[static_cast<Eigen::Index>(k)] : 0.0;
    const double scale = scaled ? p[static_cast<Eigen::Index>(k) + 1] : 1.0;
    for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = offset + scale * f[i] - y[static_cast<std::size_t>(i)];
    return r.allFinite();
  }

  // Jacobian: central differences for the tree constants, exact columns for offset and scale.
  void jacobian(const Eigen::VectorXd& p, const Eigen::VectorXd& f, Eigen::MatrixXd& jac) {
    const auto n = static_cast<Eigen::Index>(data.rows);
    Eigen::VectorXd fp(n), fm(n), rp(n), rm(n);
    const double scale = scaled ? p[static_cast<Eigen::Index>(k) + 1] : 1.0;
    for (std::size_t j = 0; j < k; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      const double h = 1e-6 * std::max(1.0, std::abs(p[jj]));
      Eigen::VectorXd q = p;
      q[jj] = p[jj] + h;
      residuals(q, fp, rp);
      q[jj] = p[jj] - h;
      residuals(q, fm, rm);
      jac.col(jj) = scale * (fp - fm) / (2.0 * h);
    }
    program.set_constants(std::span<const double>(p.data(), k));
    if (scaled) {
      jac.col(static_cast<Eigen::Index>(k)).setOnes();
      jac.col(static_cast<Eigen::Index>(k) + 1) = f;
    }
  }
};

}  // namespace

void fit_linear_scaling(std::span<const double> f, std::span<const double> y, double& offset, double& scale) {
  const double n = static_cast<double>(y.size());
  double mf = 0.0, my = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    mf += f[i];
    my += y[i];
  }
  mf /= n;
  my /= n;
  double cov = 0.0, var = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    cov += (f[i] - mf) * (y[i] - my);
    var += (f[i] - mf) * (f[i] - mf);
  }
  scale = var > 1e-300 && std::isfinite(cov / var) ? cov / var : 0.0;
  offset = my - scale * mf;
}

long optimize_constants(ScaledModel& model, const DataView& data, std::span<const double> y, int iterations,
                        bool linear_scaling) {
  const auto positions = model.tree.constant_positions();
  const std::size_t k = positions.size();
  const std::size_t m = k + (linear_scaling ? 2 : 0);
  if (m == 0 || iterations <= 0 || data.rows < m) return 0;
  Problem prob{CompiledProgram(model.tree), data, y, linear_scaling, k};
  const auto n = static_cast<Eigen::Index>(data.rows);
  Eigen::VectorXd p(static_cast<Eigen::Index>(m));
  for (std::size_t j = 0; j < k; ++j) p[static_cast<Eigen::Index>(j)] = model.tree[positions[j]].value;
  if (linear_scaling) {
    p[static_cast<Eigen::Index>(k)] = model.offset;
    p[static_cast<Eigen::Index>(k) + 1] = model.scale;
  }
  Eigen::VectorXd f(n), r(n), f_try(n), r_try(n);
  Eigen::MatrixXd jac(n, static_cast<Eigen::Index>(m));
  long evaluations = 1;
  if (!prob.residuals(p, f, r)) return evaluations;
  double sse = r.squaredNorm();
  double lambda = 1e-3;
  for (int it = 0; it < iterations && sse > 0.0; ++it) {
    prob.jacobian(p, f, jac);
    evaluations += 2 * static_cast<long>(k) + 1;
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd g = jac.transpose() * r;
    Eigen::MatrixXd a = jtj;
    a.diagonal() += lambda * jtj.diagonal() + Eigen::VectorXd::Constant(a.rows(), 1e-12 * (1.0 + jtj.diagonal().maxCoeff()));
    const Eigen::VectorXd step = a.ldlt().solve(-g);
    const Eigen::VectorXd p_try = p + step;
    if (step.allFinite() && prob.residuals(p_try, f_try, r_try) && r_try.squaredNorm() < sse) {
      p = p_try;
      f.swap(f_try);
      r.swap(r_try);
      sse = r.squaredNorm();
      lambda = std::max(lambda / 3.0, 1e-12);
    } else {
      lambda *= 3.0;
      if (lambda > 1e8) break;
    }
  }
  for (std::size_t j = 0; j < k; ++j) model.tree.nodes()[positions[j]].value = p[static_cast<Eigen::Index>(j)];
  if (linear_scaling) {
    model.offset = p[static_cast<Eigen::Index>(k)];
    model.scale = p[static_cast<Eigen::Index>(k) + 1];
  }
  return evaluations;
}

}  // namespace hs::regression
