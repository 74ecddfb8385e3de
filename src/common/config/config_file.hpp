// SPDX-License-Identifier: MIT
// Strict reading of a TOML case file into typed values (STYLE R3): every key read is recorded, and
// finish() rejects any key nobody read, so a typo can never be silently ignored.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace hs::common {

class ConfigFile;

/// One [section] of a case file. Reads throw ConfigError naming file, section, key, value and what is allowed.
/// A section that is absent from the file still answers the `_or` reads with their defaults.
class ConfigSection {
 public:
  ConfigSection(ConfigFile& file, const toml::table* table, std::string path);

  [[nodiscard]] bool has(std::string_view key) const;
  [[nodiscard]] const std::string& path() const { return path_; }

  [[nodiscard]] double positive(std::string_view key);
  [[nodiscard]] double positive_or(std::string_view key, double default_value);
  [[nodiscard]] double non_negative_or(std::string_view key, double default_value);
  [[nodiscard]] double number_in(std::string_view key, double lo, double hi);
  [[nodiscard]] double number_in_or(std::string_view key, double lo, double hi, double default_value);
  /// A number strictly greater than `lo` (e.g. tau > 0.5).
  [[nodiscard]] double greater_than(std::string_view key, double lo);
  [[nodiscard]] double greater_than_or(std::string_view key, double lo, double default_value);
  [[nodiscard]] long integer_in(std::string_view key, long lo, long hi);
  [[nodiscard]] long integer_in_or(std::string_view key, long lo, long hi, long default_value);
  [[nodiscard]] bool boolean_or(std::string_view key, bool default_value);
  [[nodiscard]] std::string string(std::string_view key);
  [[nodiscard]] std::string string_or(std::string_view key, std::string_view default_value);
  [[nodiscard]] std::string one_of(std::string_view key, std::initializer_list<std::string_view> allowed);
  [[nodiscard]] std::string one_of_or(std::string_view key, std::initializer_list<std::string_view> allowed,
                                      std::string_view default_value);
  /// A list of numbers, each within [lo, hi], at least `min_count` long.
  [[nodiscard]] std::vector<double> numbers_in(std::string_view key, double lo, double hi, std::size_t min_count = 1);
  /// A list of strings, at least `min_count` long.
  [[nodiscard]] std::vector<std::string> strings(std::string_view key, std::size_t min_count = 1);
  /// The keys present in this section, sorted (for sections whose keys are names, e.g. [validity]).
  [[nodiscard]] std::vector<std::string> keys() const;
  /// A path relative to the case file's folder, returned absolute.
  [[nodiscard]] std::filesystem::path file_path(std::string_view key);

  [[nodiscard]] ConfigSection section(std::string_view key);
  [[nodiscard]] ConfigSection section_or_empty(std::string_view key);

  /// Each quantity is given in one place only: giving both keys is an error.
  void forbid_together(std::string_view key_a, std::string_view key_b, std::string_view why);
  /// Records a value derived from others (dt from dx, tau, nu) into case.resolved.toml, under [section.derived].
  void derived(std::string_view key, double value);
  /// Throws ConfigError about `key` of this section: "<file>: [section] key = value: <what>".
  [[noreturn]] void fail(std::string_view key, std::string_view what) const;

 private:
  const toml::node* lookup(std::string_view key);
  [[nodiscard]] double number(std::string_view key, const toml::node& node) const;
  void record(std::string_view key, toml::node&& value);
  void record_copy(std::string_view key, const toml::node& node);

  ConfigFile& file_;
  const toml::table* table_;
  std::string path_;
};

/// A parsed case file. Create with load(); read through root(); call finish() after reading.
class ConfigFile {
 public:
  /// Parses the file; a missing file throws ConfigError "FILE: no such KIND" (case, closure, fit, campaign file), a
  /// malformed one names the line and column.
  static std::unique_ptr<ConfigFile> load(const std::filesystem::path& file, std::string_view kind = "case file");
  /// Parses TOML text (tests, generated cases); `name` stands in for the file name in messages.
  static std::unique_ptr<ConfigFile> parse(std::string_view text, std::string name);

  [[nodiscard]] ConfigSection root();
  [[nodiscard]] const std::filesystem::path& file() const { return file_; }
  [[nodiscard]] std::string name() const { return file_.string(); }

  /// Throws ConfigError for the first key that was never read (an unknown key or a typo).
  void finish() const;
  /// The input with every default filled in and derived values added (written as case.resolved.toml).
  [[nodiscard]] const toml::table& resolved() const { return resolved_; }
  /// Writes resolved() with an [invocation] table of how the run was asked for (`quick`: the coarse CI version of the
  /// case, whose values above are the ones it used; `resume`: continued from a checkpoint).
  void write_resolved(const std::filesystem::path& file, bool quick = false, bool resume = false) const;

 private:
  friend class ConfigSection;
  ConfigFile(toml::table table, std::filesystem::path file);
  toml::table& resolved_section(const std::string& path);

  toml::table table_;
  toml::table resolved_;
  std::filesystem::path file_;
  std::set<std::string> read_keys_;                 // "section.sub.key" for every key asked for
};

}  // namespace hs::common
