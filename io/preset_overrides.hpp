// `--set KEY=VALUE`: overrides applied to a preset's JSON document before it is read, so the
// same reader validates the result and reports the same messages as for a file (a key it does
// not know is an "unknown key" error at that path). KEY is a path as the reader's messages
// write it: drag.cd, world.wind.velocity, particles[0].velocity, variants[1].drag.model. VALUE
// is JSON (0.6, [5,5,0], {"model":"none"}, "text"), or else taken as a string (quadratic).
#pragma once

#include <string>
#include <vector>

namespace pl {

struct OverrideResult {
    std::string text;   // the document with every override applied
    std::string error;  // a KEY=VALUE that names nothing or is malformed; empty on success
};

// A document that is not valid JSON is returned unchanged: the preset reader reports why.
OverrideResult apply_preset_overrides(const std::string& json_text, const std::vector<std::string>& overrides);

}  // namespace pl
