// Errors and JSON paths of the preset reader.
#include "io/preset_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace pl {

// ------------------------------------------------------------------ errors and paths

void PresetErrorList::add(std::string path, std::string message) {
    if (message.ends_with("got null") &&
        std::find(blanked_paths_.begin(), blanked_paths_.end(), path) != blanked_paths_.end())
        return;
    if (errors_.size() < limit_)
        errors_.push_back({std::move(path), std::move(message)});
    else
        ++suppressed_;
}

std::vector<PresetError> PresetErrorList::take() {
    std::vector<PresetError> out = std::move(errors_);
    if (suppressed_ > 0) out.push_back({"", fmt::format("... and {} more errors not shown", suppressed_)});
    errors_.clear();
    suppressed_ = 0;
    return out;
}

namespace {

bool is_identifier(const std::string& key) {
    if (key.empty() || (key[0] >= '0' && key[0] <= '9')) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '$';
    });
}

}  // namespace

std::string quoted_for_message(const std::string& text) {
    constexpr std::size_t max_chars = 64;
    std::string shown = text.size() > max_chars ? text.substr(0, max_chars) : text;
    // Cutting may split a UTF-8 sequence; `replace` turns the stray bytes into U+FFFD.
    std::string out = PresetJson(shown).dump(-1, ' ', false, PresetJson::error_handler_t::replace);
    if (text.size() > max_chars) out += "...";
    return out;
}

std::string json_path_key(const std::string& parent, const std::string& key) {
    if (!is_identifier(key)) return parent + "[" + quoted_for_message(key) + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string json_path_index(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

}  // namespace pl
