// SPDX-License-Identifier: MIT
// `hemoscale validate capsule`: the dataset of cases/campaign/shear-capsule (a neo-Hookean capsule, viscosity ratio 1,
// in shear at Ca_E = 0.0125-0.2) against the steady Taylor deformation D of Ramanujan & Pozrikidis 1998 and Doddi &
// Bagchi 2008 (data/reference/capsule_shear_taylor_deformation.csv). At each Ca the run must be steady (D over its last
// quarter within 1 % of the quarter before), its npFEM converged on >= 99 % of its steps, and its D inside the two
// references' range widened by 5 % of it: the references disagree with each other by up to 7 % (0.261 against 0.279 at
// Ca_E 0.05), and the model's walls (confinement 0.133, the references' none) raise D by a per cent or two. The small-Ca
// theory D = (25/4) Ca_E (Barthes-Biesel 1980) is printed beside it. Reads the dataset only: nothing is simulated. Exit 1
// on any failure, naming it. --dataset DIR reads DIR/dataset.csv (e.g. data/resolved-shear/capsule-confinement-0.2).
// With --json FILE it also writes FILE.png (tools/plot_capsule.py).
#include "validate/capsule_validation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "common/check_list.hpp"
#include "common/run_folder.hpp"
#include "validate/plot_beside_json.hpp"
#include "validate/text_table.hpp"

namespace hs::resolved {
namespace {

namespace fs = std::filesystem;
using hs::validate::number;
using hs::validate::read_text_table;
using hs::validate::text;

constexpr double kBandWidening = 0.05;       // of the references' range, each side (see the header)
constexpr double kSteadyChange = 0.01;       // last quarter's mean D against the quarter before
constexpr double kConvergedShare = 0.99;     // #26: npFEM converged within its cap on >= 99 % of steps

/// The references' steady D at one Ca_E: the range over both sources.
struct ReferenceRange {
  double low = 1e300, high = -1e300;
  std::vector<std::string> sources;
};

}  // namespace

int validate_capsule(const hs::common::TaskOptions& options) {
  const fs::path source(HS_SOURCE_DIR);
  const fs::path reference = source / "data" / "reference" / "capsule_shear_taylor_deformation.csv";
  const fs::path folder = options.dataset ? *options.dataset : source / "data" / "resolved-shear" / "capsule";
  const fs::path csv = folder / "dataset.csv";
  std::map<double, ReferenceRange> references;   // by Ca_G, rounded to 4 digits
  const auto key = [](double ca_g) { return std::round(ca_g * 1e4) / 1e4; };
  for (const auto& row : read_text_table(reference)) {
    if (text(row, "steady") != "true") continue;   // a curve still rising at its end gives no steady value
    ReferenceRange& r = references[key(number(row, "ca_g", reference))];
    r.low = std::min(r.low, number(row, "d_low", reference));
    r.high = std::max(r.high, number(row, "d_high", reference));
    r.sources.push_back(text(row, "source"));
  }
  hs::common::CheckList checks;
  fmt::print("capsule vs Ramanujan & Pozrikidis 1998 and Doddi & Bagchi 2008 (neo-Hookean, viscosity ratio 1; dataset {})\n",
             csv.string());
  nlohmann::json result = {{"validation", "capsule"}, {"dataset", csv.string()}};
  if (!fs::exists(csv)) {
    checks.expect("the campaign's dataset", false,
                  fmt::format("{} not found: run `hemoscale campaign cases/campaign/shear-capsule`", csv.string()));
    checks.print("capsule");
    return checks.exit_code();
  }
  const double widen = kBandWidening / options.tighten;
  fmt::print("  {:>7} {:>7} {:>8} {:>15} {:>9} {:>9} {:>10}\n", "Ca_G", "Ca_E", "D", "references", "band", "25/4 Ca_E",
             "drift");
  nlohmann::json rows = nlohmann::json::array();
  std::size_t compared = 0;
  for (const auto& row : read_text_table(csv)) {
    const double ca_g = number(row, "ca", csv);
    const double d = number(row, "taylor_deformation", csv);
    const double drift = number(row, "taylor_deformation_last_quarter_change", csv);
    const double steps = number(row, "npfem_steps", csv);
    const double unconverged = number(row, "npfem_unconverged_steps", csv);
    const double linear = 25.0 / 4.0 * ca_g / 3.0;
    const auto ref = references.find(key(ca_g));
    const std::string label = fmt::format("Ca_G {:.4g}", ca_g);
    checks.expect(label + ": D steady (last quarter within 1 % of the one before)", std::abs(drift) <= kSteadyChange,
                  fmt::format("change {:+.2f} %", 100.0 * drift));
    checks.expect(label + ": npFEM converged on >= 99 % of steps", steps > 0.0 && unconverged <= (1.0 - kConvergedShare) * steps,
                  fmt::format("{:g} of {:g} steps at the cap", unconverged, steps));
    nlohmann::json out = {{"ca_g", ca_g}, {"taylor_deformation", d}, {"linear_theory", linear}, {"last_quarter_change", drift}};
    if (ref == references.end()) {
      fmt::print("  {:>7.4f} {:>7.4f} {:>8.4f} {:>15} {:>9} {:>9.4f} {:>+9.2f}%\n", ca_g, ca_g / 3.0, d, "-", "-", linear,
                 100.0 * drift);
      rows.push_back(out);
      continue;
    }
    const double lo = ref->second.low * (1.0 - widen);
    const double hi = ref->second.high * (1.0 + widen);
    fmt::print("  {:>7.4f} {:>7.4f} {:>8.4f} {:>7.3f}-{:<7.3f} {:>4.3f}-{:<4.3f} {:>9.4f} {:>+9.2f}%\n", ca_g, ca_g / 3.0, d,
               ref->second.low, ref->second.high, lo, hi, linear, 100.0 * drift);
    checks.expect(fmt::format("{}: D inside the references' range +-{:g} %", label, 100.0 * widen), d >= lo && d <= hi,
                  fmt::format("D {:.4f}; references {:.3f}-{:.3f} ({})", d, ref->second.low, ref->second.high,
                              fmt::join(ref->second.sources, "; ")));
    out["reference_range"] = {ref->second.low, ref->second.high};
    out["band"] = {lo, hi};
    out["relative_to_reference_mid"] = d / (0.5 * (ref->second.low + ref->second.high)) - 1.0;
    rows.push_back(out);
    ++compared;
  }
  checks.expect("every reference Ca has a run", compared == references.size(),
                fmt::format("{} of {} compared", compared, references.size()));
  result["runs"] = rows;
  checks.print("capsule");
  if (options.json_file) {
    result["provenance"] = hs::common::provenance();
    checks.write_to(result);
    hs::common::write_json(*options.json_file, result);
    hs::validate::plot_beside_json("plot_capsule.py", *options.json_file, reference);
  }
  return checks.exit_code();
}

}  // namespace hs::resolved
