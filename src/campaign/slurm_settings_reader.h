#pragma once
// Reads a campaign document's [slurm] table (campaign/slurm_settings.h); a header of its own so
// that slurm_settings.h does not pull toml++ into the code that only uses the settings.
#include <toml++/toml.h>

#include <filesystem>

#include "campaign/slurm_settings.h"

namespace sg {

// The [slurm] table of `doc` (absent: the defaults). Errors name `file`, the line and the key.
SlurmSettings read_slurm_settings(const std::filesystem::path& file, const toml::table& doc);

}  // namespace sg
