// Reads a parsed preset document into a Scene, collecting every problem with its JSON path.
// Internal to preset_io.cpp; the public API is preset_io.hpp.
#pragma once

#include "io/preset_io.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace pl {

// ordered_json keeps the document's key order, so errors come out in the order a reader meets them
// and saved files list sections in a fixed, readable order.
using PresetJson = nlohmann::ordered_json;

// Collects errors, keeping at most `limit` so a huge broken file cannot flood memory or a terminal.
class PresetErrorList {
public:
    explicit PresetErrorList(std::size_t limit = 1000) : limit_(limit) {}
    void add(std::string path, std::string message);
    // A value the parser had to blank out (a number too large for a double) reads as null: its
    // error is reported once by the parser, so "got null" complaints at these paths are dropped.
    void ignore_null_complaints_at(std::vector<std::string> paths) { blanked_paths_ = std::move(paths); }
    bool empty() const { return errors_.empty() && suppressed_ == 0; }
    // The collected errors, plus one whole-document line counting those left out.
    std::vector<PresetError> take();

private:
    std::size_t limit_;
    std::size_t suppressed_ = 0;
    std::vector<PresetError> errors_;
    std::vector<std::string> blanked_paths_;
};

// "room" + "size" -> "room.size"; keys that are not plain identifiers are quoted: a["x y"].
std::string json_path_key(const std::string& parent, const std::string& key);
std::string json_path_index(const std::string& parent, std::size_t index);
// A string shown inside an error message: JSON-quoted, control characters escaped, shortened.
std::string quoted_for_message(const std::string& text);

void read_preset_document(const PresetJson& doc, Scene& scene, PresetErrorList& errors);

}  // namespace pl
