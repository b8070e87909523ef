#include "io/json_csv.hpp"

#include "io/csv_writer.hpp"

#include <utility>
#include <vector>

namespace pl {

namespace {

using Json = nlohmann::ordered_json;
using Cells = std::vector<std::pair<std::string, Json>>;

void flatten(const Json& object, const std::string& prefix, const std::string& skip, Cells& out) {
    for (const auto& [key, value] : object.items()) {
        if (prefix.empty() && key == skip) continue;
        const std::string name = prefix.empty() ? key : prefix + "." + key;
        if (value.is_object()) flatten(value, name, skip, out);
        else out.emplace_back(name, value);
    }
}

void write_cell(CsvWriter& csv, const Json& value) {
    if (value.is_null()) csv.field("");
    else if (value.is_boolean()) csv.field(value.get<bool>() ? "true" : "false");
    else if (value.is_number_unsigned()) csv.field(value.get<std::uint64_t>());
    else if (value.is_number_integer()) csv.field(value.get<std::int64_t>());
    else if (value.is_number_float()) csv.field(value.get<double>());
    else if (value.is_string()) csv.field(value.get_ref<const std::string&>());
    else {  // an array of scalars
        std::string joined;
        for (const Json& item : value) joined += (joined.empty() ? "" : "; ") + (item.is_string() ? item.get<std::string>() : item.dump());
        csv.field(joined);
    }
}

}  // namespace

void write_json_rows_csv(std::ostream& out, const Json& rows, const std::string& explode) {
    std::vector<Cells> table;
    for (const Json& row : rows) {
        Cells parent;
        flatten(row, "", explode, parent);
        if (explode.empty() || !row.contains(explode)) {
            table.push_back(parent);
            continue;
        }
        for (const Json& child : row[explode]) {
            Cells cells = parent;
            flatten(child, explode, "", cells);
            table.push_back(std::move(cells));
        }
    }
    CsvWriter csv(out);
    if (table.empty()) return;
    for (const auto& [name, value] : table.front()) csv.field(name);
    csv.end_row();
    for (const Cells& cells : table) {
        for (const auto& [name, value] : cells) write_cell(csv, value);
        csv.end_row();
    }
}

}  // namespace pl
