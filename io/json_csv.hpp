// CSV from the same JSON objects a command prints with --json, so that --csv and --json cannot
// disagree on names or values: nested objects become columns named parent.child, arrays of
// scalars one cell joined by "; ", null an empty cell; numbers keep full precision.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace pl {

// One CSV row per element of `rows` (an array of objects); when `explode` names a key holding an
// array of objects, one row per element of that array instead, its fields as explode.field
// after the parent's. Columns are those of the first row.
void write_json_rows_csv(std::ostream& out, const nlohmann::ordered_json& rows, const std::string& explode = "");

}  // namespace pl
