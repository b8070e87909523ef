// One particle's trajectory metrics as JSON, with the field names of `particle-lab compare
// --json` (the GUI's state dump uses the same, so a test can hold the two side by side).
#pragma once

#include "physics/studies/expectations.hpp"
#include "physics/studies/metrics.hpp"

#include <nlohmann/json.hpp>

#include <optional>

namespace pl::cli {

// Every JSON document the CLI prints starts with "schema_version": bumped when a key is renamed
// or removed (2: unit suffixes on every dimensional key, e.g. dt_s, position_error_m).
constexpr int json_schema_version = 2;
nlohmann::ordered_json json_document();  // {"schema_version": json_schema_version}

nlohmann::ordered_json optional_json(const std::optional<double>& v);
nlohmann::ordered_json particle_metrics_json(const ParticleMetrics& p);
// A preset's expectations beside the measured values: quantity, variant, particle, expected,
// tolerance, measured (null: no value), met.
nlohmann::ordered_json expectations_json(const std::vector<ExpectationResult>& results);

}  // namespace pl::cli
