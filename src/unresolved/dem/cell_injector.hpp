// SPDX-License-Identifier: MIT
// Injection of RBC spheres through an inlet opening at a constant RBC volume flux Ht_d Q (discharge hematocrit).
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "common/geometry/opening.hpp"
#include "common/geometry/shape.hpp"
#include "unresolved/dem/domain.hpp"
#include "unresolved/dem/particle_store.hpp"

namespace hs::unresolved {

/// The fluid velocity (m/s) anywhere near an inlet, as the caller knows it (interpolated FVM field, or analytic).
using VelocityField = std::function<hs::common::Vec3(const hs::common::Vec3& x_m)>;

/// Largest discharge hematocrit accepted: a sanity bound on input, above normal systemic blood (0.37-0.53,
/// shared/reference/validation/rbc_blood_properties.csv) with room for polycythaemic blood. Whether the inlet can
/// deliver it is a separate question (random placement jams, see CellInjector::debt_cells()).
inline constexpr double max_discharge_hematocrit = 0.6;

struct InjectionSpec {
  hs::common::Opening inlet;      // kind inlet, valid for the shape and domain (check_openings)
  double discharge_hematocrit;    // Ht_d of the inflow, in (0, max_discharge_hematocrit]
  double cell_radius_m;           // of the RBC-equivalent sphere; its volume is the RBC volume injected per cell
  std::uint64_t seed;
  double slab_thickness_m = 0.0;  // new centres lie at depth r .. r + slab inside the inlet plane; 0 = one diameter
  int attempts_per_cell = 200;    // random proposals per cell before waiting for a free slot (next step)
};

/// A cell to add: centre and the local fluid velocity there.
struct NewCell {
  hs::common::Vec3 position_m;
  hs::common::Vec3 velocity_m_s;
};

/// Each step owes Ht_d Q dt more RBC volume (Q = the fluid flow rate into the inlet); whole cells are placed while
/// the debt covers one and a free slot is found, and what cannot be placed now stays owed, so there is no start-up
/// burst and no drift of the mean flux. A proposal is a centre drawn uniformly in the slab just inside the inlet
/// (depth r .. r + slab, lateral distance <= R - r); it is kept with probability u_n / u_n,max (u_n the inflow
/// velocity there, u_n,max sampled over the disc), so cells enter in proportion to the local fluid flux and the
/// inflow has the same hematocrit everywhere; it must clear the wall (signed distance <= -r) and every particle
/// present or placed (no overlap, minimum image along periodic axes). One std::mt19937_64 stream per injector:
/// the same seed and the same particles give the same cells.
class CellInjector {
 public:
  /// ConfigError naming the opening and key for a hematocrit outside (0, 0.6], an opening that is not an inlet or
  /// does not cut the shape's wall on the domain box, or a cell that does not fit through the inlet.
  CellInjector(const InjectionSpec& spec, const hs::common::Shape& shape, const Domain& domain);

  /// The cells to add after this step of dt_s; `present` are the particles now (owned ones are looked at).
  [[nodiscard]] std::vector<NewCell> plan(const ParticleStore& present, double dt_s, double flow_rate_m3_s,
                                          const VelocityField& velocity);

  [[nodiscard]] const hs::common::Opening& inlet() const { return spec_.inlet; }
  [[nodiscard]] double cell_volume_m3() const { return cell_volume_m3_; }
  /// RBC volume owed and not yet placed (m^3); below one cell volume when the inlet keeps up.
  [[nodiscard]] double debt_m3() const { return debt_m3_; }
  [[nodiscard]] double debt_cells() const { return debt_m3_ / cell_volume_m3_; }

  /// Restart: the random stream as text (std::mt19937_64's own format) and the debt; restore() continues them.
  [[nodiscard]] std::string rng_state() const;
  void restore(double debt_m3, const std::string& rng_state);

 private:
  struct Near {
    std::vector<hs::common::Vec3> x;
    std::vector<double> r;
  };
  [[nodiscard]] Near particles_near_inlet(const ParticleStore& present) const;
  [[nodiscard]] hs::common::Vec3 minimum_image(hs::common::Vec3 d) const;
  [[nodiscard]] bool overlaps(const Near& near, const hs::common::Vec3& x) const;
  [[nodiscard]] double max_inflow_speed_m_s(const VelocityField& velocity) const;
  [[nodiscard]] hs::common::Vec3 propose();

  InjectionSpec spec_;
  const hs::common::Shape& shape_;
  Domain domain_;
  hs::common::Vec3 t1_, t2_;
  double slab_m_ = 0.0;
  double cell_volume_m3_ = 0.0;
  double debt_m3_ = 0.0;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> u01_{0.0, 1.0};
};

}  // namespace hs::unresolved
