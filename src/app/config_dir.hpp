// The per-user settings directory: $XDG_CONFIG_HOME/particle-lab, else ~/.config/particle-lab.
#pragma once

#include <filesystem>
#include <cstdint>
#include <optional>

namespace pl::app {

// Created on first use; nullopt when there is no home or it cannot be created (the app then
// simply does not remember its layout).
std::optional<std::filesystem::path> user_config_dir();

// Whether a settings file may be read: a regular file (a FIFO would block start-up, /dev/zero
// would never end) of at most `max_bytes`. A missing file is not readable either.
bool readable_settings_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

}  // namespace pl::app
