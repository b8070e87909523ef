#include "io/preset_overrides.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <variant>

namespace pl {

namespace {

using Json = nlohmann::ordered_json;
using Step = std::variant<std::string, std::size_t>;  // an object key or an array index

// "particles[0].velocity" -> particles, 0, velocity; empty on a malformed path.
std::vector<Step> parse_path(const std::string& path) {
    std::vector<Step> steps;
    std::size_t i = 0;
    while (i < path.size()) {
        if (path[i] == '[') {
            const std::size_t close = path.find(']', i);
            if (close == std::string::npos || close == i + 1) return {};
            std::size_t index = 0;
            for (std::size_t k = i + 1; k < close; ++k) {
                if (!std::isdigit(static_cast<unsigned char>(path[k]))) return {};
                index = index * 10 + static_cast<std::size_t>(path[k] - '0');
            }
            steps.emplace_back(index);
            i = close + 1;
            if (i < path.size() && path[i] == '.') ++i;
            continue;
        }
        const std::size_t end = path.find_first_of(".[", i);
        const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
        if (key.empty()) return {};
        steps.emplace_back(key);
        i = end == std::string::npos ? path.size() : (path[end] == '.' ? end + 1 : end);
        if (end != std::string::npos && path[end] == '.' && i == path.size()) return {};  // trailing dot
    }
    return steps;
}

std::string path_text(const std::vector<Step>& steps, std::size_t count) {
    std::string text;
    for (std::size_t k = 0; k < count; ++k) {
        if (const auto* key = std::get_if<std::string>(&steps[k])) text += (text.empty() ? "" : ".") + *key;
        else text += fmt::format("[{}]", std::get<std::size_t>(steps[k]));
    }
    return text;
}

// Sets doc at `steps` to `value`; missing object keys are created (the reader then judges
// them), an index must name an existing element. Returns an error or "".
std::string set_at(Json& doc, const std::vector<Step>& steps, Json value) {
    Json* node = &doc;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::string where = k == 0 ? "the document" : path_text(steps, k);
        if (const auto* key = std::get_if<std::string>(&steps[k])) {
            if (!node->is_object()) return fmt::format("{} is not an object, so it has no key '{}'", where, *key);
            node = &(*node)[*key];
            if (node->is_null() && k + 1 < steps.size()) *node = Json::object();
        } else {
            const std::size_t index = std::get<std::size_t>(steps[k]);
            if (!node->is_array()) return fmt::format("{} is not an array, so it has no element [{}]", where, index);
            if (index >= node->size())
                return fmt::format("{} has {} element{}, so [{}] names nothing", where, node->size(),
                                   node->size() == 1 ? "" : "s", index);
            node = &(*node)[index];
        }
    }
    *node = std::move(value);
    return "";
}

}  // namespace

OverrideResult apply_preset_overrides(const std::string& json_text, const std::vector<std::string>& overrides) {
    OverrideResult r{json_text, ""};
    if (overrides.empty()) return r;
    Json doc = Json::parse(json_text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded()) return r;
    for (const std::string& item : overrides) {
        const std::size_t eq = item.find('=');
        const std::vector<Step> steps = eq == std::string::npos ? std::vector<Step>{} : parse_path(item.substr(0, eq));
        if (steps.empty()) {
            r.error = fmt::format("--set '{}': expected KEY=VALUE with KEY a preset path such as drag.cd or "
                                  "particles[0].velocity", item);
            return r;
        }
        const std::string text = item.substr(eq + 1);
        Json value = Json::parse(text, nullptr, false);
        if (value.is_discarded()) value = text;  // a bare word: a string such as quadratic
        const std::string error = set_at(doc, steps, std::move(value));
        if (!error.empty()) {
            r.error = fmt::format("--set {}: {}", item.substr(0, eq), error);
            return r;
        }
    }
    r.text = doc.dump(2);
    return r;
}

}  // namespace pl
