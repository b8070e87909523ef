// Text -> JSON document for the preset loader, in one linear pass: UTF-8 check, duplicate keys,
// numbers too large for a double and nesting depth are all reported with their JSON path.
// Internal to io/; the public API is preset_io.hpp.
#pragma once

#include "io/preset_reader.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace pl {

// Deepest nesting of objects and arrays a preset may have. A real preset needs 5 levels
// (variants[i].world.wind.velocity); the limit keeps memory and time linear in the file size.
constexpr std::size_t max_preset_nesting = 32;

// Parses `text` into `doc`, adding duplicate-key and overflow errors to `errors`. Returns the
// error that left no usable document (invalid UTF-8 or JSON, nesting too deep), if any.
// `blanked` receives the paths of numbers too large for a double (read as null in `doc`).
std::optional<PresetError> parse_preset_json(const std::string& text, PresetJson& doc, PresetErrorList& errors,
                                             std::vector<std::string>& blanked);

}  // namespace pl
