// SPDX-License-Identifier: MIT
// The fused kernel: streaming-store and ordinary-store paths agree bitwise; one node matches the written-out
// TRT + Guo update of the header.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "common/parallel/block_layout.hpp"
#include "resolved/lbm/aligned_allocator.hpp"
#include "resolved/lbm/equilibrium.hpp"
#include "resolved/lbm/stream_collide.hpp"

namespace hs::resolved {
namespace {

struct KernelSetup {
  common::BlockLayout layout{{21, 5, 4}, 1};
  std::size_t stride = (layout.volume() + 7) / 8 * 8;
  AlignedDoubles src, dst;
  std::vector<double> force;
  std::vector<FluidRun> runs;
  StreamCollideArgs args{};
};

KernelSetup make_setup(bool streaming) {
  KernelSetup s;
  std::mt19937 rng(42);   // fixed seed
  std::uniform_real_distribution<double> jitter(0.9, 1.1);
  s.src.resize(D3Q19::q * s.stride);
  for (std::size_t i = 0; i < D3Q19::q; ++i) {
    for (std::size_t n = 0; n < s.stride; ++n) s.src[i * s.stride + n] = D3Q19::w[i] * jitter(rng);
  }
  s.dst.assign(s.src.size(), 0.0);
  s.force.resize(3 * s.layout.volume());
  for (auto& f : s.force) f = 1e-4 * (jitter(rng) - 1.0);
  for (int z = 0; z < s.layout.n[2]; ++z) {
    for (int y = 0; y < s.layout.n[1]; ++y) s.runs.push_back({s.layout.index(y % 3, y, z), s.layout.n[0] - y % 3});
  }
  std::array<std::ptrdiff_t, D3Q19::q> offsets{};
  for (std::size_t i = 0; i < D3Q19::q; ++i) offsets[i] = s.layout.offset(D3Q19::c[i][0], D3Q19::c[i][1], D3Q19::c[i][2]);
  s.args = StreamCollideArgs{.src = s.src.data(), .dst = s.dst.data(), .volume = s.stride, .offset = offsets,
                             .runs = s.runs, .body_force = {1e-5, -2e-5, 3e-5}, .force_field = s.force.data(),
                             .force_stride = s.layout.volume(), .omega_plus = 1.0 / 0.8,
                             .omega_minus = 1.0 / (0.5 + (3.0 / 16.0) / 0.3), .regularized = false, .streaming_stores = streaming,
                             .threaded = true};
  return s;
}

TEST(StreamCollide, StreamingStoresGiveIdenticalResults) {
  KernelSetup plain = make_setup(false);
  KernelSetup streamed = make_setup(true);
  stream_collide(plain.args);
  stream_collide(streamed.args);
  ASSERT_EQ(plain.dst.size(), streamed.dst.size());
  for (std::size_t k = 0; k < plain.dst.size(); ++k) ASSERT_EQ(plain.dst[k], streamed.dst[k]) << k;
}

TEST(StreamCollide, OneNodeMatchesTheTrtGuoFormula) {
  KernelSetup s = make_setup(false);
  stream_collide(s.args);
  const int x = 7, y = 2, z = 1;
  const auto n = static_cast<std::size_t>(s.layout.index(x, y, z));
  Populations f{};
  for (std::size_t i = 0; i < D3Q19::q; ++i) f[i] = s.src[i * s.stride + n - static_cast<std::size_t>(s.args.offset[i])];
  const common::Vec3 force = s.args.body_force + common::Vec3{s.force[n], s.force[s.layout.volume() + n],
                                                               s.force[2 * s.layout.volume() + n]};
  const NodeMoments m = moments(f, force);
  const double wp = s.args.omega_plus, wm = s.args.omega_minus;
  for (int i = 0; i < D3Q19::q; ++i) {
    const int o = D3Q19::opposite(i);
    const auto& c = D3Q19::c[static_cast<std::size_t>(i)];
    const double w = D3Q19::w[static_cast<std::size_t>(i)];
    const double cu = c[0] * m.u.x + c[1] * m.u.y + c[2] * m.u.z;
    const double cf = c[0] * force.x + c[1] * force.y + c[2] * force.z;
    const double feq_p = 0.5 * (equilibrium(i, m.rho, m.u) + equilibrium(o, m.rho, m.u));
    const double feq_m = 0.5 * (equilibrium(i, m.rho, m.u) - equilibrium(o, m.rho, m.u));
    const double fp = 0.5 * (f[static_cast<std::size_t>(i)] + f[static_cast<std::size_t>(o)]);
    const double fm = 0.5 * (f[static_cast<std::size_t>(i)] - f[static_cast<std::size_t>(o)]);
    const double s_even = w * (9.0 * cu * cf - 3.0 * dot(m.u, force));
    const double s_odd = w * 3.0 * cf;
    const double expected = f[static_cast<std::size_t>(i)] - wp * (fp - feq_p) - wm * (fm - feq_m) +
                            (1.0 - 0.5 * wp) * s_even + (1.0 - 0.5 * wm) * s_odd;
    // Same formula, different order of operations: agreement to ~20 ulps of the largest population (1/3).
    EXPECT_NEAR(s.dst[static_cast<std::size_t>(i) * s.stride + n], expected, 1e-15) << "direction " << i;
  }
}

}  // namespace
}  // namespace hs::resolved
