#include "io/sweep_table.hpp"

#include "io/atomic_output.hpp"
#include "io/csv_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <fstream>
#include <sstream>

namespace pl {

namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

constexpr const char* id_prefix = "# particle-lab sweep ";

std::string header_lines(const SweepHeader& h) {
    return fmt::format("{}{}\n# points {} shard {}/{} {}\n", id_prefix, h.id, h.points, h.shard.index, h.shard.count,
                       h.shard.strided ? "strided" : "contiguous");
}

// Calls row(point, axis values, variant name, metric, value) in file order: points, then
// variants, then metrics.
template <class Row>
void for_each_row(const SweepSpec& spec, const PreparedSweep& prepared, const SweepResults& results, Row&& row) {
    for (std::size_t i = 0; i < prepared.points.size() && i < results.points.size(); ++i) {
        const std::vector<std::string> values = spec.plan.point_values(prepared.points[i]);
        const std::vector<VariantMetrics>& variants = results.points[i].variants;
        for (std::size_t v = 0; v < variants.size(); ++v)
            for (std::size_t m : spec.metrics) {
                const SweepMetric& metric = sweep_metrics()[m];
                row(prepared.points[i], values, prepared.variant_names[v], metric.name, metric.of(variants[v], spec.particle));
            }
    }
}

std::optional<std::size_t> leading_number(const std::string& text, std::size_t& end) {
    std::size_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr == text.data()) return std::nullopt;
    end = static_cast<std::size_t>(r.ptr - text.data());
    return v;
}

// "# points 71 shard 0/3 contiguous" -> header fields; false when it does not read so.
bool parse_points_line(const std::string& line, SweepHeader& h) {
    std::istringstream in(line);
    std::string hash, points, shard, slice, mode, extra;
    if (!(in >> hash >> points >> h.points >> shard >> slice >> mode) || (in >> extra) || hash != "#" ||
        points != "points" || shard != "shard" || (mode != "strided" && mode != "contiguous"))
        return false;
    h.shard.strided = mode == "strided";
    return parse_shard(slice, h.shard.strided, h.shard).empty();
}

std::string slice_name(const Shard& s) {
    return fmt::format("shard {}/{} ({})", s.index, s.count, s.strided ? "strided" : "contiguous");
}

// Every point of the file's slice, in order, each with the same number of rows.
std::string check_slice(const SweepFile& f) {
    const std::vector<std::size_t> expected = shard_points(f.header.shard, f.header.points);
    std::vector<std::size_t> seen;
    std::vector<std::size_t> rows_per_point;
    for (const auto& [point, line] : f.rows) {
        if (seen.empty() || seen.back() != point) {
            seen.push_back(point);
            rows_per_point.push_back(0);
        }
        ++rows_per_point.back();
    }
    if (seen != expected) {
        const auto first_missing = std::find_if(expected.begin(), expected.end(), [&](std::size_t p) {
            return std::find(seen.begin(), seen.end(), p) == seen.end();
        });
        return first_missing != expected.end()
                   ? fmt::format("{} lacks point {} ({} of its {} points present): incomplete",
                                 slice_name(f.header.shard), *first_missing, seen.size(), expected.size())
                   : fmt::format("{} holds points out of order or outside its slice", slice_name(f.header.shard));
    }
    for (std::size_t k = 1; k < rows_per_point.size(); ++k)
        if (rows_per_point[k] != rows_per_point[0])
            return fmt::format("point {} has {} rows, point {} has {}: incomplete", seen[k], rows_per_point[k], seen[0],
                               rows_per_point[0]);
    return "";
}

// The JSON document of a sweep, row by row: from the results (sweep --json) or from a merged CSV
// (sweep-merge --json), so that both write the same bytes for the same sweep.
class SweepJson {
public:
    SweepJson(const SweepHeader& header, std::vector<std::string> names) : names_(std::move(names)) {
        j_["sweep"] = header.id;
        j_["points"] = header.points;
        j_["shard"] = fmt::format("{}/{}", header.shard.index, header.shard.count);
        j_["axes"] = names_;
    }
    void row(std::size_t point, const std::vector<std::string>& values, const std::string& variant,
             const std::string& metric, const std::optional<double>& value) {
        Json r;
        r["point"] = point;
        for (std::size_t c = 0; c < names_.size(); ++c) {
            Json v = Json::parse(values[c], nullptr, false);  // 0.5, [5,5,0]; a bare word stays text
            r[names_[c]] = v.is_discarded() ? Json(values[c]) : v;
        }
        r["variant"] = variant;
        r["metric"] = metric;
        r["value"] = value ? Json(*value) : Json(nullptr);
        rows_.push_back(std::move(r));
    }
    std::string text() {
        j_["rows"] = std::move(rows_);
        return j_.dump(2) + "\n";
    }

private:
    std::vector<std::string> names_;
    Json j_;
    Json rows_ = Json::array();
};

// The fields of one CSV line as CsvWriter writes them (RFC 4180: quoted when they hold a comma
// or a quote, "" for a quote).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

std::optional<double> value_of(const std::string& text) {
    if (text.empty()) return std::nullopt;
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (text == "inf" || text == "-inf") return text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
    double v = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), v);  // format_double's shortest round trip
    return v;
}

}  // namespace

std::string sweep_csv(const SweepHeader& header, const SweepSpec& spec, const PreparedSweep& prepared,
                      const SweepResults& results) {
    std::ostringstream out;
    out << header_lines(header);
    CsvWriter csv(out);
    csv.field("point");
    for (const std::string& name : spec.plan.column_names()) csv.field(name);
    csv.field("variant").field("metric").field("value");
    csv.end_row();
    for_each_row(spec, prepared, results,
                 [&](std::size_t point, const std::vector<std::string>& values, const std::string& variant,
                     const char* metric, const std::optional<double>& value) {
                     csv.field(static_cast<std::uint64_t>(point));
                     for (const std::string& v : values) csv.field(v);
                     csv.field(variant).field(metric).field(value ? format_double(*value) : std::string());
                     csv.end_row();
                 });
    return out.str();
}

std::string sweep_json(const SweepHeader& header, const SweepSpec& spec, const PreparedSweep& prepared,
                       const SweepResults& results) {
    SweepJson json(header, spec.plan.column_names());
    for_each_row(spec, prepared, results,
                 [&](std::size_t point, const std::vector<std::string>& values, const std::string& variant,
                     const char* metric, const std::optional<double>& value) { json.row(point, values, variant, metric, value); });
    return json.text();
}

std::optional<SweepFile> read_sweep_file(const fs::path& file, std::string& error) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        error = fmt::format("{}: cannot read it", file.string());
        return std::nullopt;
    }
    SweepFile f;
    std::string id_line, points_line;
    std::getline(in, id_line);
    std::getline(in, points_line);
    std::getline(in, f.columns);
    if (id_line.rfind(id_prefix, 0) != 0 || !parse_points_line(points_line, f.header) || f.columns.rfind("point,", 0) != 0) {
        error = fmt::format("{}: not a sweep CSV file (it must open with '{}ID', '# points N shard I/N MODE' and the "
                            "column line 'point,...')", file.string(), id_prefix);
        return std::nullopt;
    }
    f.header.id = id_line.substr(std::string(id_prefix).size());
    std::string line;
    for (std::size_t n = 4; std::getline(in, line); ++n) {
        std::size_t end = 0;
        const std::optional<std::size_t> point = leading_number(line, end);
        if (!point || end >= line.size() || line[end] != ',') {
            error = fmt::format("{}:{}: expected a row 'POINT,...', got '{}'", file.string(), n, line.substr(0, 80));
            return std::nullopt;
        }
        f.rows.emplace_back(*point, std::move(line));
    }
    if (std::string e = check_slice(f); !e.empty()) {
        error = fmt::format("{}: {}", file.string(), e);
        return std::nullopt;
    }
    return f;
}

std::string merge_sweep_files(const std::vector<SweepFile>& shards, const std::vector<std::string>& names,
                              std::string& error) {
    if (shards.empty()) {
        error = "no shard files given";
        return "";
    }
    const SweepFile& first = shards.front();
    std::vector<int> seen(first.header.shard.count, -1);
    std::vector<std::pair<std::size_t, const std::string*>> rows;
    for (std::size_t s = 0; s < shards.size(); ++s) {
        const SweepHeader& h = shards[s].header;
        if (h.id != first.header.id || h.points != first.header.points || shards[s].columns != first.columns) {
            error = fmt::format("{} is from sweep {} ({} points), {} from sweep {} ({} points): not shards of one sweep",
                                names[s], h.id, h.points, names[0], first.header.id, first.header.points);
            return "";
        }
        if (h.shard.count != first.header.shard.count || h.shard.strided != first.header.shard.strided) {
            error = fmt::format("{} is {}, {} is {}: the shards must slice the sweep the same way", names[s],
                                slice_name(h.shard), names[0], slice_name(first.header.shard));
            return "";
        }
        if (seen[h.shard.index] >= 0) {
            error = fmt::format("{} and {} are both shard {}/{}", names[static_cast<std::size_t>(seen[h.shard.index])],
                                names[s], h.shard.index, h.shard.count);
            return "";
        }
        seen[h.shard.index] = static_cast<int>(s);
        for (const auto& [point, line] : shards[s].rows) rows.emplace_back(point, &line);
    }
    for (std::size_t i = 0; i < seen.size(); ++i)
        if (seen[i] < 0) {
            const std::vector<std::size_t> missing = shard_points({i, seen.size(), first.header.shard.strided}, first.header.points);
            error = fmt::format("shard {}/{} is missing ({} points{})", i, seen.size(), missing.size(),
                                missing.empty() ? "" : fmt::format(", from point {}", missing.front()));
            return "";
        }
    // Each point lives in one shard and a shard's rows are in point order, so a stable sort by
    // point gives the whole run's order.
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string out = header_lines({first.header.id, first.header.points, Shard{}}) + first.columns + "\n";
    for (const auto& [point, line] : rows) out += *line + "\n";
    return out;
}

std::string merged_sweep_json(const std::vector<SweepFile>& shards, const std::vector<std::string>& names,
                              std::string& error) {
    const std::string csv = merge_sweep_files(shards, names, error);
    if (!error.empty()) return "";
    const SweepFile& first = shards.front();
    std::vector<std::string> columns = csv_fields(first.columns);  // point, axes..., variant, metric, value
    const std::size_t axes = columns.size() - 4;
    SweepJson json({first.header.id, first.header.points, Shard{}},
                   std::vector<std::string>(columns.begin() + 1, columns.begin() + 1 + static_cast<std::ptrdiff_t>(axes)));
    std::istringstream in(csv);
    std::string line;
    for (int skip = 0; skip < 3; ++skip) std::getline(in, line);  // the two header lines, the columns
    while (std::getline(in, line)) {
        const std::vector<std::string> f = csv_fields(line);
        if (f.size() != columns.size()) {
            error = fmt::format("a row has {} fields, the columns {}: '{}'", f.size(), columns.size(), line.substr(0, 80));
            return "";
        }
        const std::vector<std::string> values(f.begin() + 1, f.begin() + 1 + static_cast<std::ptrdiff_t>(axes));
        json.row(std::stoull(f[0]), values, f[axes + 1], f[axes + 2], value_of(f[axes + 3]));
    }
    return json.text();
}

std::string write_file_atomically(const fs::path& file, const std::string& text) {
    AtomicOutput out(file);  // a unique temporary file beside the target, synced, then renamed
    if (out.ok()) out.stream() << text;
    if (out.ok() && out.commit()) return "";
    return "cannot write the sweep output: " + out.error();
}

}  // namespace pl
