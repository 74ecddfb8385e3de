// SPDX-License-Identifier: MIT
// `hemoscale validate resolved-dataset`: data/resolved/dataset.csv (the campaign's rows) against the campaign issue's
// acceptance rules (every grid point, finite values, 0 < DI < 1, drag along the flow, lift towards the axis) and the
// seed paper's ranges of gamma+ and Re_p. Also Cd Re_p per r*: at Re_p << 1 the drag is Stokes drag, so Cd Re_p should
// hardly depend on Re at a given r* (Oseen's correction is 3/16 Re_p, < 1 % here); a row far from its r*'s median
// is worth a look. Reads the dataset only: nothing is simulated. Exit 0 when every grid point is present, every row
// within the rules and settled (a row stopped at its cap is no result), and gamma+ and Re_p span no more than the
// paper's ranges; 1 otherwise, naming the check. --dataset FILE checks another campaign's dataset.csv.
#include "validate/resolved_dataset_validation.hpp"

#include <filesystem>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "campaign/campaign_spec.hpp"
#include "campaign/dataset_check.hpp"
#include "common/check_list.hpp"
#include "common/run_folder.hpp"

namespace hs::campaign {
namespace {

nlohmann::json range_json(const Range& r) { return {{"min", r.min}, {"max", r.max}}; }

std::string inside(const Range& ours, const Range& paper) {
  return ours.min >= paper.min && ours.max <= paper.max ? "inside" : "not inside";
}

}  // namespace

int validate_resolved_dataset(const hs::common::TaskOptions& options) {
  const std::filesystem::path source(HS_SOURCE_DIR);
  const std::filesystem::path csv = options.dataset ? *options.dataset : source / "data" / "resolved" / "dataset.csv";
  // The grid is the campaign's (the seed paper's, sec. 4); the ranges are the paper's.
  const CampaignSpec spec = read_campaign_spec(source / "cases" / "campaign" / "tube-re-rstar");
  DatasetExpectations expected;
  for (const GridAxis& axis : spec.axes) {
    std::vector<double>* values = axis.name == "re" ? &expected.re : axis.name == "r_star" ? &expected.r_star : nullptr;
    if (values == nullptr) continue;
    for (const GridValue& v : axis.values) values->push_back(std::get<double>(v));
  }
  read_published_ranges(source / "data" / "reference" / "porcaro2026_dataset_ranges.csv", expected);
  const DatasetCheck c = check_resolved_dataset(csv, expected);
  fmt::print("resolved dataset {}: {} of {} rows ({} stopped at the cap before settling)\n", csv.string(), c.rows,
             c.rows_expected, c.unsettled);
  fmt::print("  gamma+ [{:.3f}, {:.3f}]  paper [{}, {}]: {}\n", c.gamma_plus.min, c.gamma_plus.max, expected.gamma_plus.min,
             expected.gamma_plus.max, inside(c.gamma_plus, expected.gamma_plus));
  fmt::print("  Re_p   [{:.4f}, {:.4f}]  paper [{}, {}]: {}\n", c.re_p.min, c.re_p.max, expected.re_p.min, expected.re_p.max,
             inside(c.re_p, expected.re_p));
  fmt::print("  DI [{:.4f}, {:.4f}]  Cd [{:.1f}, {:.1f}]  Cl [{:.2f}, {:.2f}]\n", c.di.min, c.di.max, c.cd.min, c.cd.max,
             c.cl.min, c.cl.max);
  fmt::print("  Cd Re_p per r* (Stokes drag: about constant in Re):\n");
  nlohmann::json stokes = nlohmann::json::array();
  for (const StokesScaling& s : c.stokes) {
    fmt::print("    r* {:.1f}: {} rows, median {:.2f}, max deviation {:.1f} %\n", s.r_star, s.rows, s.median,
               100.0 * s.max_deviation);
    stokes.push_back({{"r_star", s.r_star}, {"rows", s.rows}, {"cd_re_p_median", s.median},
                      {"cd_re_p_max_deviation", s.max_deviation}});
  }
  nlohmann::json problems = nlohmann::json::array();
  for (const RowProblem& p : c.problems) {
    fmt::print("  Re {}, r* {}: {}\n", p.re, p.r_star, p.what);
    problems.push_back({{"re", p.re}, {"r_star", p.r_star}, {"problem", p.what}});
  }
  hs::common::CheckList checks;
  checks.expect("every grid point present", c.missing.empty(),
                c.missing.empty() ? fmt::format("{} rows", c.rows) : fmt::format("missing: {}", fmt::join(c.missing, "; ")));
  for (const RowProblem& p : c.problems) checks.expect(fmt::format("Re {}, r* {}", p.re, p.r_star), false, p.what);
  checks.expect("every row settled", c.unsettled == 0,
                fmt::format("{} row(s) stopped at the cap before settling (settled or cd_settled false)", c.unsettled));
  checks.expect("gamma+ inside the paper's range", inside(c.gamma_plus, expected.gamma_plus) == std::string("inside"),
                fmt::format("[{:.3f}, {:.3f}] vs [{}, {}]", c.gamma_plus.min, c.gamma_plus.max, expected.gamma_plus.min,
                            expected.gamma_plus.max));
  checks.expect("Re_p inside the paper's range", inside(c.re_p, expected.re_p) == std::string("inside"),
                fmt::format("[{:.4f}, {:.4f}] vs [{}, {}]", c.re_p.min, c.re_p.max, expected.re_p.min, expected.re_p.max));
  checks.print("resolved-dataset");
  if (options.json_file) {
    nlohmann::json result = {{"validation", "resolved-dataset"},
                             {"dataset", csv.string()},
                             {"rows", c.rows},
                             {"rows_expected", c.rows_expected},
                             {"rows_unsettled", c.unsettled},
                             {"missing", c.missing},
                             {"problems", problems},
                             {"gamma_plus", range_json(c.gamma_plus)},
                             {"gamma_plus_paper", range_json(expected.gamma_plus)},
                             {"re_p", range_json(c.re_p)},
                             {"re_p_paper", range_json(expected.re_p)},
                             {"di", range_json(c.di)},
                             {"cd", range_json(c.cd)},
                             {"cl", range_json(c.cl)},
                             {"cd_re_p_by_r_star", stokes},
                             {"complete_and_valid", c.complete_and_valid()},
                             {"provenance", hs::common::provenance()}};
    checks.write_to(result);
    hs::common::write_json(*options.json_file, result);
  }
  return checks.exit_code();
}

}  // namespace hs::campaign
