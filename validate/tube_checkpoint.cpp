// SPDX-License-Identifier: MIT
#include "validate/tube_checkpoint.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

#include "common/io/checkpoint.hpp"
#include "common/run_folder.hpp"

namespace hs::unresolved {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFingerprintFile = "fingerprint.json";

/// Whether the folder's checkpoint was written under `fingerprint` (as the archived summary is keyed).
bool written_under(const fs::path& dir, const std::string& fingerprint) {
  std::ifstream in(dir / kFingerprintFile);
  const nlohmann::json stored = nlohmann::json::parse(in, nullptr, false);
  return !stored.is_discarded() && stored.value("fingerprint", "") == fingerprint;
}

}  // namespace

fs::path tube_checkpoint_folder(const fs::path& archive) {
  fs::path dir = archive;
  return dir.replace_extension(".checkpoint");
}

TubePriesRestart tube_checkpoint(const fs::path& archive, const std::string& fingerprint) {
  const fs::path dir = tube_checkpoint_folder(archive);
  if (written_under(dir, fingerprint) && hs::common::Checkpoint::exists(dir)) return {.dir = dir, .resume = true};
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Written (atomically) before the first checkpoint: a checkpoint in this folder is always this fingerprint's.
  hs::common::write_json(dir / kFingerprintFile, {{"fingerprint", fingerprint}});
  return {.dir = dir, .resume = false};
}

void discard_tube_checkpoint(const fs::path& archive) { fs::remove_all(tube_checkpoint_folder(archive)); }

}  // namespace hs::unresolved
