// Preset files: JSON text <-> Scene (parsing, UTF-8 and overflow handling, pretty printing,
// atomic saving). The format itself (every key, unit, bound and default) is defined once by the
// rows in physics/model/schema/*_fields.hpp; `particle-lab validate --format` prints it, and
// README.md ("Presets") embeds that text. The reader and the writer that iterate the rows are
// io/preset_reader.cpp and io/preset_writer.cpp.
#include "io/preset_io.hpp"

#include "io/preset_reader.hpp"
#include "io/preset_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {

namespace {

// ------------------------------------------------------------------ parsing

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

// Builds the document like nlohmann's own DOM parser, and also tracks the JSON path of every
// value so that (a) a key given twice is reported (nlohmann would silently keep one of them) and
// (b) a number too large for a double, which nlohmann rejects as a parse error, can be named by
// its path instead of only its byte offset.
class PathTrackingSax {
public:
    using number_integer_t = PresetJson::number_integer_t;
    using number_unsigned_t = PresetJson::number_unsigned_t;
    using number_float_t = PresetJson::number_float_t;
    using string_t = PresetJson::string_t;
    using binary_t = PresetJson::binary_t;

    PathTrackingSax(PresetJson& root, PresetErrorList& errors) : root_(root), errors_(errors) {}

    bool null() { return value(nullptr); }
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
        if (!top.keys.insert(k).second)
            errors_.add(json_path_key(top.path, k), "duplicate key (each key may appear only once)");
        object_element_ = &(*top.value)[k];
        return true;
    }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool parse_error(std::size_t position, const std::string& last_token, const PresetJson::exception& ex) {
        error_position = position;
        error_token = last_token;
        error_id = ex.id;
        error_what = ex.what();
        error_path = child_path();
        return false;
    }

    std::size_t error_position = 0;
    std::string error_token, error_what, error_path;
    int error_id = 0;

private:
    struct Frame {
        PresetJson* value;
        bool object;
        std::string path;
        std::set<std::string> keys;
        std::string key;
        std::size_t index = 0;
    };

    std::string child_path() const {
        if (frames_.empty()) return "";
        const Frame& top = frames_.back();
        return top.object ? json_path_key(top.path, top.key) : json_path_index(top.path, top.index);
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
        ++top.index;
        top.value->push_back(std::move(v));
        return &top.value->back();
    }

    template <class T>
    bool value(T&& v) {
        place(PresetJson(std::forward<T>(v)));
        return true;
    }

    bool open(PresetJson&& empty, bool object) {
        const std::string path = child_path();
        PresetJson* where = place(std::move(empty));
        frames_.push_back(Frame{where, object, path, {}, {}, 0});
        return true;
    }

    bool close() {
        frames_.pop_back();
        return true;
    }

    PresetJson& root_;
    PresetErrorList& errors_;
    std::vector<Frame> frames_;
    PresetJson* object_element_ = nullptr;
};

// A number that overflows a double, found (and blanked out) while parsing.
struct OverflowedNumber {
    std::string path;
    std::string text;
};

std::string strip_exception_id(const std::string& what) {
    // "[json.exception.parse_error.101] parse error at line 1, column 5: ..." -> "parse error at ..."
    const std::size_t end = what.find("] ");
    return what.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? what.substr(end + 2) : what;
}

// ------------------------------------------------------------------ serialising

// Scalars use nlohmann's own dump: doubles in the shortest form that reads back to the same value.
std::string scalar_text(const PresetJson& j) { return j.dump(-1, ' ', false, PresetJson::error_handler_t::replace); }

bool is_scalar(const PresetJson& j) { return !j.is_object() && !j.is_array(); }

// One-line form, used for arrays of numbers and for small flat objects (a particle, the air).
std::string inline_text(const PresetJson& j) {
    if (is_scalar(j)) return scalar_text(j);
    std::string out = j.is_object() ? "{ " : "[";
    bool first = true;
    for (const auto& item : j.items()) {
        if (!first) out += ", ";
        first = false;
        if (j.is_object()) out += scalar_text(PresetJson(item.key())) + ": ";
        out += inline_text(item.value());
    }
    out += j.is_object() ? (j.empty() ? "}" : " }") : "]";
    return out;
}

bool fits_on_one_line(const PresetJson& j, std::size_t indent) {
    constexpr std::size_t line_width = 100;
    if (j.is_array()) return std::all_of(j.begin(), j.end(), is_scalar);
    if (j.is_object()) {
        for (const auto& item : j.items())
            if (item.value().is_object() || (item.value().is_array() && !fits_on_one_line(item.value(), 0))) return false;
        return indent + inline_text(j).size() <= line_width;
    }
    return true;
}

void write_pretty(const PresetJson& j, std::size_t indent, std::string& out) {
    if (is_scalar(j) || j.empty() || fits_on_one_line(j, indent)) {
        out += inline_text(j);
        return;
    }
    const std::string pad(indent + 2, ' ');
    out += j.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (const auto& item : j.items()) {
        if (!first) out += ",\n";
        first = false;
        out += pad;
        if (j.is_object()) out += scalar_text(PresetJson(item.key())) + ": ";
        write_pretty(item.value(), indent + 2, out);
    }
    out += "\n" + std::string(indent, ' ') + (j.is_object() ? "}" : "]");
}

// ------------------------------------------------------------------ files

std::string quoted_path(const std::filesystem::path& p) {
    // Built by appending: GCC 12 gives a false -Wrestrict for "'" + std::string&&.
    std::string out(1, '\'');
    out += p.string();
    out += '\'';
    return out;
}

LoadResult file_error(std::string message) {
    LoadResult r;
    r.errors.push_back({"", std::move(message)});
    return r;
}

bool write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

std::string LoadResult::error_text() const {
    std::string out;
    for (const PresetError& e : errors) {
        if (!out.empty()) out += '\n';
        out += e.to_string();
    }
    return out;
}

LoadResult parse_preset(const std::string& json_text) {
    LoadResult result;
    if (auto bad = first_invalid_utf8(json_text)) {
        result.errors.push_back({"", utf8_error(json_text, *bad)});
        return result;
    }
    // JSON has no NaN or Inf, but a literal such as 1e400 overflows a double and nlohmann stops
    // there. To still report every error, each such number is blanked to `null` (padded, so line
    // and column numbers stay right) and the text parsed again; its path gets a "finite" error.
    constexpr std::size_t max_overflows = 100;
    std::string text = json_text;
    std::vector<OverflowedNumber> overflows;
    PresetJson doc;
    PresetErrorList errors;
    for (;;) {
        doc = PresetJson();
        errors = PresetErrorList();
        PathTrackingSax sax(doc, errors);
        if (PresetJson::sax_parse(text, &sax)) break;
        const std::size_t length = sax.error_token.size();
        const bool overflow = sax.error_id == 406 && length >= 4 && sax.error_position >= length &&
                              text.compare(sax.error_position - length, length, sax.error_token) == 0;
        if (!overflow || overflows.size() == max_overflows) {
            result.errors.push_back({"", "not valid JSON: " + strip_exception_id(sax.error_what)});
            return result;
        }
        overflows.push_back({sax.error_path, sax.error_token});
        text.replace(sax.error_position - length, length, "null" + std::string(length - 4, ' '));
    }

    // Parse-time errors (duplicate keys) come first, then the overflows, then the reader's.
    std::vector<std::string> blanked;
    for (const OverflowedNumber& o : overflows) {
        blanked.push_back(o.path);
        if (o.path.empty())
            errors.add("", "expected a JSON object at the top level, got a number too large for a double");
        else
            errors.add(o.path, "must be finite, but the number " +
                                   (o.text.size() > 32 ? o.text.substr(0, 32) + "..." : o.text) +
                                   " is too large for a double");
    }
    errors.ignore_null_complaints_at(std::move(blanked));
    Scene scene;
    read_preset_document(doc, scene, errors);
    result.errors = errors.take();
    if (result.errors.empty()) result.scene = std::move(scene);
    return result;
}

LoadResult load_preset(const std::filesystem::path& file) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) return file_error("cannot open preset " + quoted_path(file) + ": no such file");
    if (ec) return file_error("cannot open preset " + quoted_path(file) + ": " + ec.message());
    if (fs::is_directory(status)) return file_error(quoted_path(file) + " is a directory, not a preset file");
    if (!fs::is_regular_file(status)) return file_error(quoted_path(file) + " is not a regular file");
    const std::uintmax_t size = fs::file_size(file, ec);
    const auto too_large = [&](std::uintmax_t bytes) {
        return file_error(fmt::format("preset {} is too large ({} bytes; at most {} bytes)", quoted_path(file), bytes,
                                      max_preset_file_bytes));
    };
    if (!ec && size > max_preset_file_bytes) return too_large(size);

    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) return file_error("cannot open preset " + quoted_path(file) + ": " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    std::size_t n = 0;
    // Bounded even if the file grows while being read.
    while (text.size() <= max_preset_file_bytes && (n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    const int read_errno = errno;
    std::fclose(f);
    if (failed) return file_error("cannot read preset " + quoted_path(file) + ": " + std::strerror(read_errno));
    if (text.size() > max_preset_file_bytes) return too_large(text.size());
    return parse_preset(text);
}

std::string serialize_preset(const Scene& scene) {
    std::string out;
    write_pretty(preset_document(scene), 0, out);
    out += '\n';
    return out;
}

SaveResult save_preset(const std::filesystem::path& file, const Scene& scene) {
    namespace fs = std::filesystem;
    const std::string target = quoted_path(file);
    const std::string text = serialize_preset(scene);
    // Never write a file that would not load back.
    if (LoadResult check = parse_preset(text); !check.ok())
        return {false, "not saving " + target + ": the scene is not valid:\n" + check.error_text()};
    if (text.size() > max_preset_file_bytes)
        return {false, fmt::format("not saving {}: the preset would be {} bytes, more than the {} a preset may have "
                                   "(use an emitter for many particles)",
                                   target, text.size(), max_preset_file_bytes)};
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    const bool exists = fs::exists(status);
    if (fs::is_directory(status)) return {false, "cannot save preset to " + target + ": it is a directory"};

    fs::path tmp = file;
    tmp += ".tmp";
    fs::path bak = file;
    bak += ".bak";
    const auto fail = [&](const std::string& what, int error_number, bool remove_tmp) {
        if (remove_tmp) ::unlink(tmp.c_str());  // unlink never removes a directory
        return SaveResult{false, "cannot save preset to " + target + ": " + what + ": " + std::strerror(error_number) +
                                     " (the existing file is unchanged)"};
    };

    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) return fail("cannot create " + quoted_path(tmp), errno, false);
    struct stat previous {};
    if (exists && ::stat(file.c_str(), &previous) == 0) ::fchmod(fd, previous.st_mode & 07777);  // keep its permissions
    if (!write_all(fd, text) || ::fsync(fd) != 0) {
        const int e = errno;
        ::close(fd);
        return fail("cannot write " + quoted_path(tmp), e, true);
    }
    if (::close(fd) != 0) return fail("cannot write " + quoted_path(tmp), errno, true);

    if (exists) {
        fs::copy_file(file, bak, fs::copy_options::overwrite_existing, ec);
        if (ec) return fail("cannot keep the previous file as " + quoted_path(bak), ec.value(), true);
    }
    if (::rename(tmp.c_str(), file.c_str()) != 0) return fail("cannot rename " + quoted_path(tmp) + " over it", errno, true);

    // Make the rename itself durable (best effort: not every file system supports it).
    const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
    if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return {true, ""};
}

}  // namespace pl
