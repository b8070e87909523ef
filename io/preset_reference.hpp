// Text generated from the preset format's rows (physics/model/schema/): the format reference that
// `particle-lab validate --format` prints and README.md embeds, and the fuzz dictionary.
#pragma once

#include "physics/model/schema/schema_tree.hpp"

#include <string>

namespace pl {

std::string preset_format_reference();

// A value as the reference and the GUI show it: 1.81e-05, [0, -9.81, 0], "Untitled", null.
std::string default_text(const schema::DefaultValue& v);

// "> 0, <= 1e+06", "in [0, 1]", "finite": a number's bounds, in the reader's message form.
std::string bounds_text(const schema::Bounds& b);

}  // namespace pl

namespace pl {

// libFuzzer dictionary lines ("\"key\"") for every key, the format's name and every enumeration
// value, each once, in the order the format reference lists them.
std::string preset_fuzz_dictionary();

}  // namespace pl
