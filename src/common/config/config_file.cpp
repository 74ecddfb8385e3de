// SPDX-License-Identifier: MIT
// Strict reading of a TOML case file into typed values.
#include "common/config/config_file.hpp"
#include "common/config/toml_floats.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace hs::common {
namespace {

std::string join_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string show(const toml::node& node) {
  std::ostringstream s;
  if (const auto* str = node.as_string()) {
    s << '"' << str->get() << '"';
  } else if (const auto* f = node.as_floating_point()) {
    s << fmt::format("{}", f->get());   // shortest form that round-trips: what the user typed
  } else {
    node.visit([&s](const auto& v) { s << v; });
  }
  return s.str();
}

std::string list_allowed(std::initializer_list<std::string_view> allowed) {
  std::string out;
  for (auto a : allowed) out += (out.empty() ? "\"" : ", \"") + std::string(a) + "\"";
  return out;
}

/// Optimal string alignment distance (Damerau-Levenshtein without repeated edits of one substring):
/// insertions, deletions, substitutions and swaps of two adjacent characters each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

/// The candidate closest to `key`, if close enough to be a likely typo: at most 2 edits, or a third of the length.
std::optional<std::string> closest(std::string_view key, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
  std::optional<std::string> best;
  std::size_t best_d = limit + 1;
  for (const auto& c : candidates) {
    const std::size_t dist = edit_distance(key, c);
    if (dist < best_d) {
      best_d = dist;
      best = c;
    }
  }
  return best;
}

}  // namespace

ConfigSection::ConfigSection(ConfigFile& file, const toml::table* table, std::string path)
    : file_(file), table_(table), path_(std::move(path)) {}

bool ConfigSection::has(std::string_view key) const { return table_ != nullptr && table_->contains(key); }

const toml::node* ConfigSection::lookup(std::string_view key) {
  file_.read_keys_.insert(join_path(path_, key));
  return table_ == nullptr ? nullptr : table_->get(key);
}

void ConfigSection::fail(std::string_view key, std::string_view what) const {
  const std::string where = path_.empty() ? std::string(key) : fmt::format("[{}] {}", path_, key);
  const toml::node* node = table_ == nullptr ? nullptr : table_->get(key);
  if (node == nullptr) {
    // A required key is missing: a key present here that nobody read and that is close to it is probably its typo.
    std::vector<std::string> unread;
    for (const auto& k : keys()) {
      if (k != key && file_.read_keys_.count(join_path(path_, k)) == 0) unread.push_back(k);
    }
    const auto typo = closest(key, unread);
    const std::string hint = typo ? fmt::format(" (the file has {}, did you mean {}?)", *typo, key) : "";
    throw ConfigError(fmt::format("{}: {}: {}{}", file_.name(), where, what, hint));
  }
  throw ConfigError(fmt::format("{}: {} = {}: {}", file_.name(), where, show(*node), what));
}

double ConfigSection::number(std::string_view key, const toml::node& node) const {
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  fail(key, "must be a number");
}

void ConfigSection::record(std::string_view key, toml::node&& value) {
  auto& section = file_.resolved_section(path_);
  value.visit([&](auto&& v) { section.insert_or_assign(key, std::move(v)); });
}

void ConfigSection::record_copy(std::string_view key, const toml::node& node) {
  auto& section = file_.resolved_section(path_);
  node.visit([&](const auto& v) { section.insert_or_assign(key, v); });
}

double ConfigSection::positive(std::string_view key) {
  return greater_than(key, 0.0);
}

double ConfigSection::positive_or(std::string_view key, double default_value) {
  return greater_than_or(key, 0.0, default_value);
}

double ConfigSection::non_negative_or(std::string_view key, double default_value) {
  return number_in_or(key, 0.0, HUGE_VAL, default_value);
}

double ConfigSection::greater_than(std::string_view key, double lo) {
  const toml::node* node = lookup(key);
  if (node == nullptr) fail(key, fmt::format("missing; a number > {} is required", lo));
  const double v = number(key, *node);
  if (!(v > lo) || !std::isfinite(v)) fail(key, fmt::format("must be a finite number > {}", lo));
  record(key, toml::value<double>(v));
  return v;
}

double ConfigSection::greater_than_or(std::string_view key, double lo, double default_value) {
  if (has(key)) return greater_than(key, lo);
  lookup(key);
  record(key, toml::value<double>(default_value));
  return default_value;
}

double ConfigSection::number_in(std::string_view key, double lo, double hi) {
  const toml::node* node = lookup(key);
  if (node == nullptr) fail(key, fmt::format("missing; a number in [{}, {}] is required", lo, hi));
  const double v = number(key, *node);
  if (!(v >= lo && v <= hi) || !std::isfinite(v)) fail(key, fmt::format("must be a finite number in [{}, {}]", lo, hi));
  record(key, toml::value<double>(v));
  return v;
}

double ConfigSection::number_in_or(std::string_view key, double lo, double hi, double default_value) {
  if (has(key)) return number_in(key, lo, hi);
  lookup(key);
  record(key, toml::value<double>(default_value));
  return default_value;
}

long ConfigSection::integer_in(std::string_view key, long lo, long hi) {
  const toml::node* node = lookup(key);
  if (node == nullptr) fail(key, fmt::format("missing; an integer in [{}, {}] is required", lo, hi));
  const auto* i = node->as_integer();
  if (i == nullptr) fail(key, fmt::format("must be an integer in [{}, {}]", lo, hi));
  const long v = static_cast<long>(i->get());
  if (v < lo || v > hi) fail(key, fmt::format("must be an integer in [{}, {}]", lo, hi));
  record(key, toml::value<int64_t>(v));
  return v;
}

long ConfigSection::integer_in_or(std::string_view key, long lo, long hi, long default_value) {
  if (has(key)) return integer_in(key, lo, hi);
  lookup(key);
  record(key, toml::value<int64_t>(default_value));
  return default_value;
}

bool ConfigSection::boolean_or(std::string_view key, bool default_value) {
  const toml::node* node = lookup(key);
  bool v = default_value;
  if (node != nullptr) {
    const auto* b = node->as_boolean();
    if (b == nullptr) fail(key, "must be true or false");
    v = b->get();
  }
  record(key, toml::value<bool>(v));
  return v;
}

std::string ConfigSection::string(std::string_view key) {
  const toml::node* node = lookup(key);
  if (node == nullptr) fail(key, "missing; a string is required");
  const auto* s = node->as_string();
  if (s == nullptr) fail(key, "must be a string");
  record(key, toml::value<std::string>(s->get()));
  return s->get();
}

std::string ConfigSection::string_or(std::string_view key, std::string_view default_value) {
  if (has(key)) return string(key);
  lookup(key);
  record(key, toml::value<std::string>(std::string(default_value)));
  return std::string(default_value);
}

std::string ConfigSection::one_of(std::string_view key, std::initializer_list<std::string_view> allowed) {
  if (!has(key)) {
    lookup(key);
    fail(key, fmt::format("missing; one of {} is required", list_allowed(allowed)));
  }
  const std::string v = string(key);
  for (auto a : allowed) {
    if (v == a) return v;
  }
  fail(key, fmt::format("must be one of {}", list_allowed(allowed)));
}

std::string ConfigSection::one_of_or(std::string_view key, std::initializer_list<std::string_view> allowed,
                                     std::string_view default_value) {
  if (has(key)) return one_of(key, allowed);
  lookup(key);
  record(key, toml::value<std::string>(std::string(default_value)));
  return std::string(default_value);
}

std::vector<double> ConfigSection::numbers_in(std::string_view key, double lo, double hi, std::size_t min_count) {
  const toml::node* node = lookup(key);
  const std::string what = fmt::format("must be a list of at least {} numbers in [{}, {}]", min_count, lo, hi);
  if (node == nullptr) fail(key, "missing; " + what);
  const auto* arr = node->as_array();
  if (arr == nullptr || arr->size() < min_count) fail(key, what);
  std::vector<double> out;
  for (const auto& el : *arr) {
    double v = 0.0;
    if (const auto* f = el.as_floating_point()) {
      v = f->get();
    } else if (const auto* i = el.as_integer()) {
      v = static_cast<double>(i->get());
    } else {
      fail(key, what);
    }
    if (!(v >= lo && v <= hi)) fail(key, what);
    out.push_back(v);
  }
  record_copy(key, *node);
  return out;
}

std::vector<std::string> ConfigSection::strings(std::string_view key, std::size_t min_count) {
  const toml::node* node = lookup(key);
  const std::string what = fmt::format("must be a list of at least {} strings", min_count);
  if (node == nullptr) fail(key, "missing; " + what);
  const auto* arr = node->as_array();
  if (arr == nullptr || arr->size() < min_count) fail(key, what);
  std::vector<std::string> out;
  for (const auto& el : *arr) {
    const auto* s = el.as_string();
    if (s == nullptr) fail(key, what);
    out.push_back(s->get());
  }
  record_copy(key, *node);
  return out;
}

std::vector<std::string> ConfigSection::keys() const {
  std::vector<std::string> out;
  if (table_ != nullptr) {
    for (const auto& [k, v] : *table_) out.emplace_back(k.str());
  }
  return out;
}

std::filesystem::path ConfigSection::file_path(std::string_view key) {
  const std::filesystem::path p = string(key);
  return p.is_absolute() ? p : file_.file().parent_path() / p;
}

ConfigSection ConfigSection::section(std::string_view key) {
  const toml::node* node = lookup(key);
  if (node == nullptr) fail(key, "missing section");
  const auto* t = node->as_table();
  if (t == nullptr) fail(key, "must be a table [section]");
  file_.resolved_section(join_path(path_, key));
  return {file_, t, join_path(path_, key)};
}

ConfigSection ConfigSection::section_or_empty(std::string_view key) {
  if (has(key)) return section(key);
  lookup(key);
  file_.resolved_section(join_path(path_, key));
  return {file_, nullptr, join_path(path_, key)};
}

void ConfigSection::forbid_together(std::string_view key_a, std::string_view key_b, std::string_view why) {
  if (has(key_a) && has(key_b)) {
    fail(key_b, fmt::format("is redundant with {} ({}); give only one of them", key_a, why));
  }
}

void ConfigSection::derived(std::string_view key, double value) {
  file_.resolved_section(join_path(path_, "derived")).insert_or_assign(key, value);
}

ConfigFile::ConfigFile(toml::table table, std::filesystem::path file) : table_(std::move(table)), file_(std::move(file)) {}

std::unique_ptr<ConfigFile> ConfigFile::load(const std::filesystem::path& file, std::string_view kind) {
  if (!std::filesystem::is_regular_file(file)) {
    throw ConfigError(fmt::format("{}: no such {}", file.string(), kind));
  }
  try {
    return std::unique_ptr<ConfigFile>(new ConfigFile(toml::parse_file(file.string()), file));
  } catch (const toml::parse_error& e) {
    throw ConfigError(fmt::format("{}:{}:{}: malformed TOML: {}", file.string(), e.source().begin.line,
                                  e.source().begin.column, e.description()));
  }
}

std::unique_ptr<ConfigFile> ConfigFile::parse(std::string_view text, std::string name) {
  try {
    return std::unique_ptr<ConfigFile>(new ConfigFile(toml::parse(text), std::filesystem::path(name)));
  } catch (const toml::parse_error& e) {
    throw ConfigError(fmt::format("{}:{}:{}: malformed TOML: {}", name, e.source().begin.line, e.source().begin.column,
                                  e.description()));
  }
}

ConfigSection ConfigFile::root() { return {*this, &table_, ""}; }

toml::table& ConfigFile::resolved_section(const std::string& path) {
  toml::table* t = &resolved_;
  std::size_t start = 0;
  while (start < path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!t->contains(part)) t->insert(part, toml::table{});
    t = t->get(part)->as_table();
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return *t;
}

void ConfigFile::finish() const {
  // Depth-first walk: the first key never asked for is reported with the keys its section does allow.
  auto walk = [this](auto&& self, const toml::table& t, const std::string& path) -> void {
    for (const auto& [k, v] : t) {
      const std::string full = join_path(path, k.str());
      if (read_keys_.count(full) == 0) {
        std::string allowed;
        std::vector<std::string> allowed_keys;
        const std::string prefix = path.empty() ? "" : path + ".";
        for (const auto& r : read_keys_) {
          if (r.rfind(prefix, 0) == 0 && r.find('.', prefix.size()) == std::string::npos) {
            allowed += (allowed.empty() ? "" : ", ") + r.substr(prefix.size());
            allowed_keys.push_back(r.substr(prefix.size()));
          }
        }
        const auto guess = closest(k.str(), allowed_keys);
        const std::string hint = guess ? fmt::format("did you mean {}? ", *guess) : "";
        const std::string where = path.empty() ? std::string(k.str()) : fmt::format("[{}] {}", path, k.str());
        throw ConfigError(fmt::format("{}: {}: unknown key ({}allowed here: {})", file_.string(), where, hint,
                                      allowed.empty() ? "none" : allowed));
      }
      if (const auto* sub = v.as_table()) self(self, *sub, full);
    }
  };
  walk(walk, table_, "");
}

void ConfigFile::write_resolved(const std::filesystem::path& file, bool quick, bool resume) const {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
  out << "# Written by hemoscale: the case as run, every default filled in, derived values under [*.derived].\n";
  if (quick) out << "# Run with --quick: the coarse, short CI version of the case; a smoke test, not a result.\n";
  toml::table as_run = resolved_;
  as_run.insert_or_assign("invocation", toml::table{{"quick", quick}, {"resume", resume}});
  std::ostringstream text;
  text << as_run << '\n';
  out << with_shortest_floats(text.str());   // 1e-05 as written, not 1.0000000000000001e-05
}

}  // namespace hs::common
