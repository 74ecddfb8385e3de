// SPDX-License-Identifier: MIT
// The three closure fits of cases/regression/synthetic recover the known formulas of the synthetic dataset, and the
// closure files they write load back as closures that evaluate those formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>

#include "closures/closure_fit.hpp"
#include "closures/register_builtin.hpp"

namespace fs = std::filesystem;
namespace hc = hs::closures;

namespace {

const fs::path cases = fs::path(HS_SOURCE_DIR) / "cases/regression/synthetic";

// The formulas of tools/make_synthetic_dataset.py.
double di_truth(const hc::ClosureInputs& in) { return 0.6 * in.gamma_plus / (0.08 + in.gamma_plus) - 0.3 * in.u_r_plus; }
double cd_truth(const hc::ClosureInputs& in) { return 24.0 / in.re_p * (1.0 + 0.5 * in.di); }
double cl_truth(const hc::ClosureInputs& in) { return 1.5 * in.di / std::sqrt(in.re_p); }

// Largest relative deviation over 2000 random points inside the validity box.
double max_relative_error(const std::function<double(const hc::ClosureInputs&)>& model,
                          const std::function<double(const hc::ClosureInputs&)>& truth) {
  std::mt19937_64 rng(5);
  auto u = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const hc::ClosureInputs in{.re_p = u(0.015, 0.115), .gamma_plus = u(0.03, 0.34), .u_r_plus = u(-0.14, -0.02),
                               .di = u(0.15, 0.5)};
    worst = std::max(worst, std::abs(model(in) - truth(in)) / std::abs(truth(in)));
  }
  return worst;
}

fs::path fit(const std::string& folder) {
  const auto request = hc::read_fit_request(cases / folder / "fit.toml");
  const fs::path out = fs::temp_directory_path() / ("hs_fit_" + folder);
  fs::remove_all(out);
  const auto closure = hc::run_fit(request, out, true);
  return out / (closure.name + ".toml");
}

}  // namespace

// Exact recovery: the learned formula equals the generating one to 1e-9 relative everywhere in the box
// (LM converges to round-off on noise-free data; 1e-9 leaves room for its last digits). The formula itself is
// compared, unclamped: the test box reaches a little past the training rows the validity box is made of.
TEST(SyntheticRecovery, DeformationIndex) {
  const auto c = hc::make_deformation_closure({.model = "expression", .file = fit("deformation_index"), .outside = hc::OutsideValidity::extrapolate});
  EXPECT_LT(max_relative_error([&](const auto& in) { return c->deformation_index(in); }, di_truth), 1e-9);
}

TEST(SyntheticRecovery, DragCoefficient) {
  const auto c = hc::make_drag_closure({.model = "expression", .file = fit("drag_coefficient"), .outside = hc::OutsideValidity::extrapolate});
  EXPECT_LT(max_relative_error([&](const auto& in) { return c->drag_coefficient(in); }, cd_truth), 1e-9);
}

TEST(SyntheticRecovery, LiftCoefficient) {
  const auto c = hc::make_lift_closure({.model = "expression", .file = fit("lift_coefficient"), .outside = hc::OutsideValidity::extrapolate});
  EXPECT_LT(max_relative_error([&](const auto& in) { return c->lift_coefficient(in); }, cl_truth), 1e-9);
}
