// Scene -> preset document, by iterating the format's rows (physics/model/schema/*_fields.hpp):
// every field is written, defaults included, so a saved file loads back identical.
// Internal to preset_io.cpp; the public API is preset_io.hpp.
#pragma once

#include "io/preset_reader.hpp"

namespace pl {

PresetJson preset_document(const Scene& scene);

}  // namespace pl
