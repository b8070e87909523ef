// The preset format as a JSON Schema (draft 2020-12), generated from the rows
// (physics/model/schema/); `particle-lab schema` prints it.
#pragma once

#include <string>

namespace pl {

// Pretty-printed, two-space indent.
std::string preset_json_schema();

}  // namespace pl
