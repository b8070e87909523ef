// One particle's trajectory metrics as JSON, with the field names of `particle-lab compare
// --json` (the GUI's state dump uses the same, so a test can hold the two side by side).
#pragma once

#include "physics/studies/metrics.hpp"

#include <nlohmann/json.hpp>

#include <optional>

namespace pl::cli {

nlohmann::ordered_json optional_json(const std::optional<double>& v);
nlohmann::ordered_json particle_metrics_json(const ParticleMetrics& p);

}  // namespace pl::cli
