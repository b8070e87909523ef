#include "cli/trajectory_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

namespace pl::cli {

namespace {

bool parse_index(const std::string& text, std::size_t& out) {
    const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
    return !text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size();
}

}  // namespace

std::string parse_particle_list(const std::string& text, std::size_t count, std::vector<std::size_t>& out) {
    out.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        const std::size_t dash = item.find('-');
        std::size_t first = 0, last = 0;
        const bool ok = dash == std::string::npos ? parse_index(item, first) && parse_index(item, last)
                                                  : parse_index(item.substr(0, dash), first) &&
                                                        parse_index(item.substr(dash + 1), last) && first <= last;
        if (!ok)
            return fmt::format("--particles: expected indices and ranges such as 0,3-5, got '{}' in '{}'", item, text);
        if (last >= count)
            return fmt::format("--particles: particle {} does not exist (the preset has {} particle{}, 0 to {})", last,
                               count, count == 1 ? "" : "s", count - 1);
        for (std::size_t i = first; i <= last; ++i) out.push_back(i);
        start = comma + 1;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return "";
}

std::uint64_t trajectory_rows_bound(std::uint64_t base_steps, std::uint64_t every, std::uint64_t particles,
                                    std::uint64_t variants) {
    const std::uint64_t points = base_steps / std::max<std::uint64_t>(every, 1) + 2;
    return points * particles * variants;
}

std::string trajectory_size_warning(const std::string& path, std::uint64_t bytes) {
    if (bytes < trajectory_warning_bytes) return "";
    return fmt::format("--out '{}' will be about {:.1f} GB; write fewer rows with --every K (every K-th step) or "
                       "--particles LIST (e.g. 0,3-5), or a smaller binary file with --out NAME.npy",
                       path, static_cast<double>(bytes) / 1e9);
}

}  // namespace pl::cli
