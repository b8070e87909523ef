#include "io/preset_parse.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pl {

namespace {

// ------------------------------------------------------------------ UTF-8

struct Utf8Problem {
    std::size_t offset;
    unsigned char byte;
};

// Validates UTF-8 per RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF.
std::optional<Utf8Problem> first_invalid_utf8(const std::string& text) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            ++i;
            continue;
        }
        std::size_t length = 0;
        unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
        if (c >= 0xC2 && c <= 0xDF) length = 2;
        else if (c == 0xE0) length = 3, lo = 0xA0;
        else if (c >= 0xE1 && c <= 0xEC) length = 3;
        else if (c == 0xED) length = 3, hi = 0x9F;
        else if (c >= 0xEE && c <= 0xEF) length = 3;
        else if (c == 0xF0) length = 4, lo = 0x90;
        else if (c >= 0xF1 && c <= 0xF3) length = 4;
        else if (c == 0xF4) length = 4, hi = 0x8F;
        else return Utf8Problem{i, c};
        if (i + length > n) return Utf8Problem{i, c};
        // A broken sequence is reported at its first byte, e.g. Latin-1 "\xE9" in "caf\xE9".
        if (s[i + 1] < lo || s[i + 1] > hi) return Utf8Problem{i, c};
        for (std::size_t k = 2; k < length; ++k)
            if (s[i + k] < 0x80 || s[i + k] > 0xBF) return Utf8Problem{i, c};
        i += length;
    }
    return std::nullopt;
}

std::string utf8_error(const std::string& text, const Utf8Problem& p) {
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < p.offset; ++i)
        if (text[i] == '\n') ++line, line_start = i + 1;
    return fmt::format("not valid UTF-8 text: invalid byte 0x{:02X} at line {}, column {} (byte offset {}); "
                       "save the preset as UTF-8",
                       p.byte, line, p.offset - line_start + 1, p.offset);
}

// ------------------------------------------------------------------ numbers too large for a double

// A number literal that overflows a double: where it is, and which scalar value of the document
// it is (counted in document order, keys excluded), so the SAX parser can name its path.
struct OverflowedNumber {
    std::size_t offset = 0;
    std::size_t length = 0;
    std::size_t value_index = 0;
    std::string path;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// JSON's number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
bool is_json_number(std::string_view t) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t start = i;
        while (i < t.size() && is_digit(t[i])) ++i;
        return i > start;
    };
    if (i < t.size() && t[i] == '-') ++i;
    if (i < t.size() && t[i] == '0') ++i;
    else if (!digits()) return false;
    if (i < t.size() && t[i] == '.' && (++i, !digits())) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        if (!digits()) return false;
    }
    return i == t.size();
}

bool overflows_double(std::string_view t) {
    // Without an exponent a literal needs more than 308 digits to overflow; most numbers are
    // short, so strtod runs only on the few that could.
    if (t.find_first_of("eE") == std::string_view::npos && t.size() <= 308) return false;
    if (!is_json_number(t)) return false;  // the JSON parser reports it as a syntax error
    const std::string copy(t);
    const double x = std::strtod(copy.c_str(), nullptr);
    return x == HUGE_VAL || x == -HUGE_VAL;
}

// One linear scan for number literals that overflow a double (nlohmann stops at the first one).
// It counts scalar values in document order; in valid JSON a string is a key exactly when the
// next non-blank character is ':'. In invalid JSON the parser stops with its own error first.
std::vector<OverflowedNumber> find_overflowing_numbers(const std::string& text, std::size_t at_most) {
    std::vector<OverflowedNumber> found;
    const std::size_t n = text.size();
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    std::size_t values = 0;
    for (std::size_t i = 0; i < n && found.size() < at_most;) {
        const char c = text[i];
        if (c == '"') {
            std::size_t j = i + 1;
            while (j < n && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
            i = j + 1;
            std::size_t k = i;
            while (k < n && blank(text[k])) ++k;
            if (k >= n || text[k] != ':') ++values;
        } else if (c == '-' || is_digit(c)) {
            std::size_t j = i;
            while (j < n && (is_digit(text[j]) || text[j] == '-' || text[j] == '+' || text[j] == '.' ||
                             text[j] == 'e' || text[j] == 'E'))
                ++j;
            if (overflows_double(std::string_view(text).substr(i, j - i))) found.push_back({i, j - i, values, ""});
            ++values;
            i = j;
        } else if (c >= 'a' && c <= 'z') {  // true, false, null
            while (i < n && text[i] >= 'a' && text[i] <= 'z') ++i;
            ++values;
        } else {
            ++i;
        }
    }
    return found;
}

// ------------------------------------------------------------------ SAX

// Builds the document like nlohmann's own DOM parser, and also tracks the JSON path of every
// value so that (a) a key given twice is reported (nlohmann would silently keep one of them),
// (b) a blanked number too large for a double is named by its path and (c) nesting deeper than
// max_preset_nesting stops the parse. Keys are found through a hash index per object: the
// ordered_json map itself searches linearly, which made 200k keys take 30 s.
class PathTrackingSax {
public:
    using number_integer_t = PresetJson::number_integer_t;
    using number_unsigned_t = PresetJson::number_unsigned_t;
    using number_float_t = PresetJson::number_float_t;
    using string_t = PresetJson::string_t;
    using binary_t = PresetJson::binary_t;

    PathTrackingSax(PresetJson& root, PresetErrorList& errors, std::vector<OverflowedNumber>& overflows)
        : root_(root), errors_(errors), overflows_(overflows) {}

    bool null() {
        if (next_overflow_ < overflows_.size() && overflows_[next_overflow_].value_index == values_)
            overflows_[next_overflow_++].path = child_path();
        return value(nullptr);
    }
    bool boolean(bool v) { return value(v); }
    bool number_integer(number_integer_t v) { return value(v); }
    bool number_unsigned(number_unsigned_t v) { return value(v); }
    bool number_float(number_float_t v, const string_t& /*text*/) { return value(v); }
    bool string(string_t& v) { return value(v); }
    bool binary(binary_t& v) { return value(PresetJson::binary(v)); }

    bool start_object(std::size_t /*elements*/) { return open(PresetJson::object(), true); }
    bool start_array(std::size_t /*elements*/) { return open(PresetJson::array(), false); }
    bool key(string_t& k) {
        Frame& top = frames_.back();
        top.key = k;
        auto& members = top.value->get_ref<PresetJson::object_t&>();
        const auto [slot, added] = top.index.try_emplace(k, members.size());
        if (added) {
            // A new key: append without the map's own linear search.
            members.PresetJson::object_t::Container::emplace_back(k, PresetJson());
        } else {
            errors_.add(json_path_key(top.path, k), "duplicate key (each key may appear only once)");
        }
        object_element_ = &static_cast<PresetJson::object_t::Container&>(members)[slot->second].second;
        return true;
    }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool parse_error(std::size_t position, const std::string& /*last_token*/, const PresetJson::exception& ex) {
        error_position = position;
        error_what = ex.what();
        return false;
    }

    std::size_t error_position = 0;
    std::string error_what;
    std::string too_deep_path;  // set when nesting passed max_preset_nesting

private:
    struct Frame {
        PresetJson* value;
        bool object;
        std::string path;
        std::unordered_map<std::string, std::size_t> index;  // key -> position in the object
        std::string key;
        std::size_t index_in_array = 0;
    };

    std::string child_path() const {
        if (frames_.empty()) return "";
        const Frame& top = frames_.back();
        return top.object ? json_path_key(top.path, top.key) : json_path_index(top.path, top.index_in_array);
    }

    // Places a finished value in its parent; returns where it now lives.
    PresetJson* place(PresetJson&& v) {
        if (frames_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Frame& top = frames_.back();
        if (top.object) {
            *object_element_ = std::move(v);
            return object_element_;
        }
        ++top.index_in_array;
        top.value->push_back(std::move(v));
        return &top.value->back();
    }

    template <class T>
    bool value(T&& v) {
        ++values_;
        place(PresetJson(std::forward<T>(v)));
        return true;
    }

    bool open(PresetJson&& empty, bool object) {
        std::string path = child_path();
        if (frames_.size() >= max_preset_nesting) {
            too_deep_path = path;  // at most 32 keys of at most 64 characters each
            return false;
        }
        PresetJson* where = place(std::move(empty));
        frames_.push_back(Frame{where, object, std::move(path), {}, {}, 0});
        return true;
    }

    bool close() {
        frames_.pop_back();
        return true;
    }

    PresetJson& root_;
    PresetErrorList& errors_;
    std::vector<OverflowedNumber>& overflows_;
    std::size_t next_overflow_ = 0;
    std::size_t values_ = 0;  // scalar values seen so far, in document order
    std::vector<Frame> frames_;
    PresetJson* object_element_ = nullptr;
};

std::string strip_exception_id(const std::string& what) {
    // "[json.exception.parse_error.101] parse error at line 1, column 5: ..." -> "parse error at ..."
    const std::size_t end = what.find("] ");
    return what.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? what.substr(end + 2) : what;
}

}  // namespace

std::optional<PresetError> parse_preset_json(const std::string& json_text, PresetJson& doc, PresetErrorList& errors,
                                             std::vector<std::string>& blanked) {
    if (auto bad = first_invalid_utf8(json_text)) return PresetError{"", utf8_error(json_text, *bad)};
    // JSON has no NaN or Inf, but a literal such as 1e400 overflows a double and nlohmann stops
    // there. To still report every error in one parse, each such number (up to 100; the next
    // one is reported by nlohmann) is blanked to `null`, padded so line and column numbers stay
    // right; its path gets a "finite" error.
    constexpr std::size_t max_overflows = 100;
    std::vector<OverflowedNumber> overflows = find_overflowing_numbers(json_text, max_overflows);
    std::string blanked_text;
    if (!overflows.empty()) {
        blanked_text = json_text;
        for (const OverflowedNumber& o : overflows) blanked_text.replace(o.offset, o.length, "null" + std::string(o.length - 4, ' '));
    }
    PathTrackingSax sax(doc, errors, overflows);
    if (!PresetJson::sax_parse(overflows.empty() ? json_text : blanked_text, &sax)) {
        if (!sax.too_deep_path.empty())
            return PresetError{sax.too_deep_path,
                               fmt::format("objects and arrays nested more than {} levels deep (a preset needs 5)",
                                           max_preset_nesting)};
        return PresetError{"", "not valid JSON: " + strip_exception_id(sax.error_what)};
    }
    // Parse-time errors (duplicate keys) come first, then the overflows, then the reader's.
    for (const OverflowedNumber& o : overflows) {
        blanked.push_back(o.path);
        const std::string literal = json_text.substr(o.offset, std::min<std::size_t>(o.length, 33));
        if (o.path.empty())
            errors.add("", "expected a JSON object at the top level, got a number too large for a double");
        else
            errors.add(o.path, "must be finite, but the number " + (o.length > 32 ? literal.substr(0, 32) + "..." : literal) +
                                   " is too large for a double");
    }
    return std::nullopt;
}

}  // namespace pl
