// SPDX-License-Identifier: MIT
#include "validate/tube_checkpoint.hpp"

#include <fstream>
#include <iterator>

#include "common/io/checkpoint.hpp"

namespace hs::unresolved {
namespace {

namespace fs = std::filesystem;

fs::path folder_of(const fs::path& archive) {
  fs::path dir = archive;
  return dir.replace_extension(".checkpoint");
}

constexpr const char* kFingerprintFile = "fingerprint.json";

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TubePriesRestart tube_checkpoint(const fs::path& archive, const std::string& fingerprint) {
  const fs::path dir = folder_of(archive);
  const bool same_tube = fs::exists(dir / kFingerprintFile) && read_text(dir / kFingerprintFile) == fingerprint;
  if (same_tube && hs::common::Checkpoint::exists(dir)) return {.dir = dir, .resume = true};
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Written before the first checkpoint: a checkpoint in this folder is always this fingerprint's.
  const fs::path tmp = dir / (std::string(kFingerprintFile) + ".tmp");
  std::ofstream(tmp, std::ios::binary) << fingerprint;
  fs::rename(tmp, dir / kFingerprintFile);
  return {.dir = dir, .resume = false};
}

void discard_tube_checkpoint(const fs::path& archive) { fs::remove_all(folder_of(archive)); }

}  // namespace hs::unresolved
