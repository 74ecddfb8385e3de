// SPDX-License-Identifier: MIT
// Where one tube of a validation table keeps its restart file while it runs, so an interrupted table resumes the
// tube it was running instead of starting it again (a D = 100 um tube runs for hours).
#pragma once

#include <filesystem>
#include <string>

#include "unresolved/cases/tube_pries.hpp"

namespace hs::unresolved {

/// X.tubes/D30_ht0.10_seed1.json -> X.tubes/D30_ht0.10_seed1.checkpoint/ (what tube_checkpoint prepares).
[[nodiscard]] std::filesystem::path tube_checkpoint_folder(const std::filesystem::path& archive);

/// The restart folder of the tube archived at `archive` (X.tubes/D30_ht0.10_seed1.json ->
/// X.tubes/D30_ht0.10_seed1.checkpoint/), holding the tube's fingerprint beside the checkpoint. Resumes only when a
/// checkpoint is there and was written under the same fingerprint (model, closures, numerics, seed); anything else
/// in the folder is removed and the tube starts from rest, so a checkpoint of another model is never continued.
[[nodiscard]] TubePriesRestart tube_checkpoint(const std::filesystem::path& archive, const std::string& fingerprint);

/// Removes the tube's restart folder once its summary is archived (the summary is the result; the folder would
/// only take space in the results folder).
void discard_tube_checkpoint(const std::filesystem::path& archive);

}  // namespace hs::unresolved
