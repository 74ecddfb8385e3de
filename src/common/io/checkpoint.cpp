// SPDX-License-Identifier: MIT
// Restart files: named arrays plus a JSON header, replaced atomically.
#include "common/io/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/io/atomic_file.hpp"

namespace hs::common {
namespace {

constexpr char magic[8] = {'H', 'S', 'C', 'K', 'P', 'T', '0', '1'};

void put_u64(std::ostream& out, std::uint64_t v) { out.write(reinterpret_cast<const char*>(&v), 8); }

std::uint64_t get_u64(std::istream& in) {
  std::uint64_t v = 0;
  in.read(reinterpret_cast<char*>(&v), 8);
  if (!in) throw std::runtime_error("truncated");
  return v;
}

std::string get_string(std::istream& in, std::uint64_t n) {
  if (n > (1ull << 32)) throw std::runtime_error("corrupt length");
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  if (!in) throw std::runtime_error("truncated");
  return s;
}

template <typename T>
void write_arrays(std::ostream& out, const std::map<std::string, std::vector<T>>& arrays) {
  put_u64(out, arrays.size());
  for (const auto& [name, values] : arrays) {
    put_u64(out, name.size());
    out.write(name.data(), static_cast<std::streamsize>(name.size()));
    put_u64(out, values.size());
    out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(T)));
  }
}

template <typename T>
void read_arrays(std::istream& in, std::map<std::string, std::vector<T>>& arrays) {
  const std::uint64_t n = get_u64(in);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::string name = get_string(in, get_u64(in));
    const std::uint64_t count = get_u64(in);
    std::vector<T> values(count);
    in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(T)));
    if (!in) throw std::runtime_error("truncated array " + name);
    arrays.emplace(name, std::move(values));
  }
}

}  // namespace

void Checkpoint::put(const std::string& name, std::span<const double> values) {
  doubles_[name].assign(values.begin(), values.end());
}

void Checkpoint::put(const std::string& name, std::span<const std::int64_t> values) {
  integers_[name].assign(values.begin(), values.end());
}

bool Checkpoint::has(const std::string& name) const { return doubles_.count(name) > 0 || integers_.count(name) > 0; }

const std::vector<double>& Checkpoint::doubles(const std::string& name) const {
  const auto it = doubles_.find(name);
  if (it == doubles_.end()) throw std::runtime_error("checkpoint has no double array " + name);
  return it->second;
}

const std::vector<std::int64_t>& Checkpoint::integers(const std::string& name) const {
  const auto it = integers_.find(name);
  if (it == integers_.end()) throw std::runtime_error("checkpoint has no integer array " + name);
  return it->second;
}

std::filesystem::path Checkpoint::file_for(const std::filesystem::path& dir, int rank) {
  return dir / fmt::format("state.rank{:04d}.bin", rank);
}

bool Checkpoint::exists(const std::filesystem::path& dir, int rank) { return std::filesystem::is_regular_file(file_for(dir, rank)); }

void Checkpoint::write(const std::filesystem::path& dir, int rank) const {
  std::filesystem::create_directories(dir);
  write_file_atomic(file_for(dir, rank), [this](std::ostream& out) {
    out.write(magic, sizeof magic);
    const std::string header = meta_.dump();
    put_u64(out, header.size());
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    write_arrays(out, doubles_);
    write_arrays(out, integers_);
    out.write(magic, sizeof magic);   // trailer: a complete file ends with the magic again
  });
}

Checkpoint Checkpoint::read(const std::filesystem::path& dir, int rank) {
  const auto file = file_for(dir, rank);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(fmt::format("{}: no checkpoint to resume from", file.string()));
  Checkpoint c;
  try {
    char head[8];
    in.read(head, 8);
    if (!in || std::memcmp(head, magic, 8) != 0) throw std::runtime_error("not a hemoscale checkpoint");
    c.meta_ = nlohmann::json::parse(get_string(in, get_u64(in)));
    read_arrays(in, c.doubles_);
    read_arrays(in, c.integers_);
    in.read(head, 8);
    if (!in || std::memcmp(head, magic, 8) != 0) throw std::runtime_error("missing trailer");
  } catch (const std::exception& e) {
    throw ConfigError(fmt::format("{}: corrupt checkpoint ({})", file.string(), e.what()));
  }
  return c;
}

CheckpointSchedule::CheckpointSchedule(double interval_s) : interval_s_(interval_s), last_(std::chrono::steady_clock::now()) {}

bool CheckpointSchedule::due() {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_s_) return false;
  last_ = now;
  return true;
}

}  // namespace hs::common
