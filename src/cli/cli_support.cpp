#include "cli/cli_support.hpp"

#include "io/preset_io.hpp"
#include "io/preset_overrides.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace pl::cli {

void print_error(const std::string& command, const std::string& message) {
    std::fprintf(stderr, "particle-lab %s: %s\n", command.c_str(), message.c_str());
}

namespace {
std::size_t max_preset_bytes = max_preset_file_bytes;  // --max-preset-bytes of the running command
}

void add_max_preset_bytes_option(CLI::App& command) {
    command.add_option("--max-preset-bytes", max_preset_bytes, "largest preset file read, in bytes")
        ->capture_default_str()
        ->check(positive_integer());
}

namespace {

// At most max_preset_bytes + 1 bytes of `in`: one byte more tells that the limit was passed.
std::optional<std::string> read_bounded(std::istream& in) {
    std::string text;
    char buffer[1 << 16];
    while (text.size() <= max_preset_bytes && in.read(buffer, sizeof buffer).gcount() > 0)
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (in.bad()) return std::nullopt;
    return text;
}

// The preset as read by load_preset, or (given overrides or "-") its text read here, overridden
// and parsed by the same parse_preset. A file this cannot read is left to load_preset, whose
// message says why.
LoadResult load_with_overrides(const std::string& command, const std::string& path, const std::vector<std::string>& sets) {
    if (sets.empty() && path != "-") return load_preset(path, max_preset_bytes);
    std::optional<std::string> text;
    if (path == "-") {
        text = read_bounded(std::cin);
        if (!text || text->size() > max_preset_bytes) {
            LoadResult r;
            r.errors.push_back({"", text ? fmt::format("the preset on standard input is larger than {} bytes", max_preset_bytes)
                                         : "cannot read the preset from standard input"});
            return r;
        }
    } else {
        std::ifstream file(path, std::ios::binary);
        if (file) text = read_bounded(file);
        if (!text || text->size() > max_preset_bytes || std::filesystem::is_directory(path)) return load_preset(path, max_preset_bytes);
    }
    const OverrideResult overridden = apply_preset_overrides(*text, sets);
    if (!overridden.error.empty()) {
        print_error(command, overridden.error);
        return {};
    }
    return parse_preset(overridden.text);
}

}  // namespace

std::optional<Scene> load_scene(const std::string& command, const std::string& path, const std::vector<std::string>& sets) {
    LoadResult r = load_with_overrides(command, path, sets);
    if (r.ok()) return std::move(r.scene);
    if (r.errors.empty()) return std::nullopt;  // an override error, already printed
    if (r.errors.size() == 1 && r.errors.front().path.empty()) {  // the file itself: missing, unreadable, ...
        print_error(command, r.errors.front().message +
                                 (r.over_size_limit ? "; raise it with --max-preset-bytes BYTES" : ""));
        return std::nullopt;
    }
    print_error(command, fmt::format("{}: not a valid preset ({} error{}):", path == "-" ? "standard input" : path, r.errors.size(),
                                     r.errors.size() == 1 ? "" : "s"));
    const std::string text = r.error_text();
    std::fprintf(stderr, "%s%s", text.c_str(), !text.empty() && text.back() != '\n' ? "\n" : "");
    return std::nullopt;
}

std::string printable(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        // C0 controls, DEL, and the C1 controls U+0080..U+009F (UTF-8 0xC2 0x80..0x9F): a
        // terminal would act on them (clear the screen, set the title) instead of showing them.
        if (c < 0x20 || c == 0x7F) {
            out += fmt::format("\\x{:02x}", c);
        } else if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) < 0xA0 &&
                   static_cast<unsigned char>(text[i + 1]) >= 0x80) {
            out += fmt::format("\\u{:04x}", static_cast<unsigned char>(text[++i]));
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

void add_set_option(CLI::App* command, std::vector<std::string>& sets) {
    command->add_option("--set", sets,
                        "KEY=VALUE: override a preset field by its path before the preset is validated\n"
                        "(repeatable), e.g. --set drag.cd=0.6 --set particles[0].velocity=[5,5,0]")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
}

void add_quiet_flag(CLI::App* command) {
    command->add_flag_callback("-q,--quiet", [] { set_quiet(true); }, "no progress and no warnings on stderr (errors only)");
}

std::string variant_label(const Scene& scene, std::size_t variant) {
    return scene.variants.empty() ? "" : scene.variants[variant].label;
}

std::string variant_name(const Scene& scene, std::size_t variant) {
    if (scene.variants.empty() || scene.variants[variant].label.empty()) return std::to_string(variant);
    return scene.variants[variant].label;
}

void Table::print(std::FILE* out) const {
    std::vector<std::size_t> width(header.size(), 0);
    auto measure = [&](const std::vector<std::string>& row) {
        for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
    };
    measure(header);
    for (const auto& row : rows) measure(row);
    auto line = [&](const std::vector<std::string>& row) {
        std::string s;
        for (std::size_t c = 0; c < width.size(); ++c) {
            const std::string cell = c < row.size() ? row[c] : "";
            const std::string pad(width[c] - std::min(width[c], cell.size()), ' ');
            if (c > 0) s += "  ";
            s += c == 0 ? cell + pad : pad + cell;
        }
        while (!s.empty() && s.back() == ' ') s.pop_back();
        std::fprintf(out, "%s\n", s.c_str());
    };
    line(header);
    std::size_t total = 0;
    for (std::size_t w : width) total += w;
    std::fprintf(out, "%s\n", std::string(total + 2 * (width.empty() ? 0 : width.size() - 1), '-').c_str());
    for (const auto& row : rows) line(row);
}

std::string sig(double value, int digits) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return fmt::format("{:.{}g}", value, digits);
}

std::string sig(const std::optional<double>& value, int digits) { return value ? sig(*value, digits) : "-"; }

CLI::Validator positive_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double v = 0.0;
            const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
            if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v) || v <= 0.0)
                return fmt::format("must be a number > 0, got '{}'", text);
            return "";
        },
        "NUMBER>0");
}

CLI::Validator whole_number_at_least(unsigned long long least) {
    return CLI::Validator(
        [least](std::string& text) -> std::string {
            unsigned long long v = 0;
            // from_chars into an unsigned type refuses "-1" (strtoull would wrap it to 2^64 - 1).
            const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
            if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || v < least)
                return fmt::format("must be a whole number >= {}, got '{}'", least, text);
            return "";
        },
        fmt::format("INTEGER>={}", least));
}

CLI::Validator positive_integer() { return whole_number_at_least(1); }

std::optional<std::size_t> find_variant(const Scene& scene, const std::string& text) {
    for (std::size_t v = 0; v < variant_count(scene); ++v)
        if (variant_name(scene, v) == text) return v;
    std::size_t index = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), index);
    if (!text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size() && index < variant_count(scene))
        return index;
    return std::nullopt;
}

std::string variant_list(const Scene& scene) {
    std::string names;
    for (std::size_t v = 0; v < variant_count(scene); ++v) names += (v ? ", '" : "'") + variant_name(scene, v) + "'";
    return names;
}

namespace {
std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto first = item.find_first_not_of(" \t");
        const auto last = item.find_last_not_of(" \t");
        items.push_back(first == std::string::npos ? "" : item.substr(first, last - first + 1));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}
}  // namespace

std::string parse_double_list(const std::string& option, const std::string& text, std::vector<double>& out) {
    out.clear();
    for (const std::string& item : split_commas(text)) {
        double v = 0.0;
        const auto r = std::from_chars(item.data(), item.data() + item.size(), v);
        if (item.empty() || r.ec != std::errc() || r.ptr != item.data() + item.size() || !std::isfinite(v) || v <= 0.0)
            return fmt::format("{}: expected a comma-separated list of numbers > 0, got '{}' in '{}'", option, item, text);
        out.push_back(v);
    }
    return "";
}

std::string parse_method_list(const std::string& option, const std::string& text, std::vector<Method>& out) {
    out.clear();
    for (const std::string& item : split_commas(text)) {
        const std::optional<Method> m = method_from_string(item);
        if (!m)
            return fmt::format("{}: unknown method '{}'; expected a comma-separated list of explicit_euler, "
                               "semi_implicit_euler, velocity_verlet, rk4, dopri5, exponential",
                               option, item);
        out.push_back(*m);
    }
    return "";
}

}  // namespace pl::cli
