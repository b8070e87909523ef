// The per-user settings directory: $XDG_CONFIG_HOME/particle-lab, else ~/.config/particle-lab.
#pragma once

#include <filesystem>
#include <optional>

namespace pl::app {

// Created on first use; nullopt when there is no home or it cannot be created (the app then
// simply does not remember its layout).
std::optional<std::filesystem::path> user_config_dir();

}  // namespace pl::app
