// Preset files: JSON text <-> Scene (parsing, UTF-8 and overflow handling, pretty printing,
// atomic saving). The format itself (every key, unit, bound and default) is defined once by the
// rows in physics/model/schema/*_fields.hpp; `particle-lab validate --format` prints it, and
// README.md ("Presets") embeds that text. The reader and the writer that iterate the rows are
// io/preset_reader.cpp and io/preset_writer.cpp.
#include "io/preset_io.hpp"

#include "io/atomic_output.hpp"
#include "io/preset_parse.hpp"
#include "io/preset_reader.hpp"
#include "io/preset_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {

namespace {

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
    // Appended piece by piece: GCC 12 gives a false -Wrestrict for "\n" + std::string&&.
    out += '\n';
    out.append(indent, ' ');
    out += j.is_object() ? '}' : ']';
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
    PresetJson doc;
    PresetErrorList errors;
    std::vector<std::string> blanked;
    if (std::optional<PresetError> fatal = parse_preset_json(json_text, doc, errors, blanked)) {
        result.errors.push_back(std::move(*fatal));
        return result;
    }
    errors.ignore_null_complaints_at(std::move(blanked));
    Scene scene;
    read_preset_document(doc, scene, errors);
    result.errors = errors.take();
    if (result.errors.empty()) result.scene = std::move(scene);
    return result;
}

LoadResult load_preset(const std::filesystem::path& file, std::size_t max_bytes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) return file_error("cannot open preset " + quoted_path(file) + ": no such file");
    if (ec) return file_error("cannot open preset " + quoted_path(file) + ": " + ec.message());
    if (fs::is_directory(status)) return file_error(quoted_path(file) + " is a directory, not a preset file");
    if (!fs::is_regular_file(status)) return file_error(quoted_path(file) + " is not a regular file");
    const std::uintmax_t size = fs::file_size(file, ec);
    const auto too_large = [&](std::uintmax_t bytes) {
        LoadResult r = file_error(fmt::format("preset {} is too large ({} bytes; the preset size limit is {} bytes)",
                                              quoted_path(file), bytes, max_bytes));
        r.over_size_limit = true;
        return r;
    };
    if (!ec && size > max_bytes) return too_large(size);

    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) return file_error("cannot open preset " + quoted_path(file) + ": " + std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    std::size_t n = 0;
    // Bounded even if the file grows while being read.
    while (text.size() <= max_bytes && (n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    const int read_errno = errno;
    std::fclose(f);
    if (failed) return file_error("cannot read preset " + quoted_path(file) + ": " + std::strerror(read_errno));
    if (text.size() > max_bytes) return too_large(text.size());
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
    // A symlinked preset is saved through the link: the file it leads to is replaced.
    const fs::path real = write_target(file);
    std::error_code ec;
    const fs::file_status status = fs::status(real, ec);
    const bool exists = fs::exists(status);
    if (fs::is_directory(status)) return {false, "cannot save preset to " + target + ": it is a directory"};

    // A unique temporary name per save: two writers of the same preset never share one.
    fs::path tmp;
    fs::path bak = real;
    bak += ".bak";
    const auto fail = [&](const std::string& what, int error_number, bool remove_tmp) {
        if (remove_tmp) ::unlink(tmp.c_str());  // unlink never removes a directory
        return SaveResult{false, "cannot save preset to " + target + ": " + what + ": " + std::strerror(error_number) +
                                     " (the existing file is unchanged)"};
    };

    const int fd = create_temp_beside(real, tmp);
    if (fd < 0) return fail("cannot create a temporary file beside it", errno, false);
    struct stat previous {};
    if (exists && ::stat(real.c_str(), &previous) == 0) ::fchmod(fd, previous.st_mode & 07777);  // keep its permissions
    if (!write_all(fd, text) || ::fsync(fd) != 0) {
        const int e = errno;
        ::close(fd);
        return fail("cannot write " + quoted_path(tmp), e, true);
    }
    if (::close(fd) != 0) return fail("cannot write " + quoted_path(tmp), errno, true);

    if (exists) {
        fs::copy_file(real, bak, fs::copy_options::overwrite_existing, ec);
        if (ec) return fail("cannot keep the previous file as " + quoted_path(bak), ec.value(), true);
    }
    if (::rename(tmp.c_str(), real.c_str()) != 0) return fail("cannot rename " + quoted_path(tmp) + " over it", errno, true);

    // Make the rename itself durable (best effort: not every file system supports it).
    const fs::path dir = real.has_parent_path() ? real.parent_path() : fs::path(".");
    if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return {true, ""};
}

}  // namespace pl
