// Preset files: JSON text <-> Scene.
//
// Format "particle-lab-preset", version 1. Keys (SI units; [x, y, z] arrays; y is up):
//
//   format        "particle-lab-preset"                                          required
//   version       1                                                              required
//   name          string                                      default "Untitled"
//   description   string                                      default ""
//   room          { center [m], size [m] }                                       required
//                   size > 0 in every axis, <= 1e6
//   world         { gravity [m/s^2]                           default [0, -9.81, 0]
//                   air  { density [kg/m^3]                   default 1.225 (sea level)
//                          viscosity [Pa s] }                 default 1.81e-5
//                   wind { kind: none | constant | gust | shear | vortex     default none
//                          velocity [m/s]       constant: the wind; gust: the mean;
//                                               shear: the wind at reference_height
//                          amplitude [m/s]      gust: bounded variation per axis
//                          period [s]           gust: dominant period of the variation
//                          seed                 gust: seed of the variation (integer >= 0)
//                          reference_height [m] shear: height above the floor where |w| = |velocity|
//                          exponent             shear: power-law (Hellmann) exponent, 0..1
//                          center [m]           vortex: a point on the axis
//                          axis                 vortex: axis direction (not zero)
//                          max_speed [m/s]      vortex: tangential speed at core_radius
//                          core_radius [m] } }  vortex: radius of the solid-body core
//   drag          { model: none | linear | quadratic | sphere_re           default none
//                   cd                          quadratic: drag coefficient, default 0.47
//                   b [N s/m] }                 linear: explicit coefficient; null or omitted: Stokes 6 pi mu R
//   contact       { restitution (0..1), friction (Coulomb mu >= 0), rest_speed [m/s] }
//   integrator    { method: explicit_euler | semi_implicit_euler | velocity_verlet | rk4 | dopri5 | exponential
//                   dt [s] (0 < dt <= 1), rtol, atol, adaptive (dopri5 only: true/false) }
//   particles     [ { position [m] (required), velocity [m/s], mass [kg], radius [m] } ]
//   emitter       { count (required), seed, region_min [m], region_max [m], speed_min [m/s],
//                   speed_max [m/s], direction, spread_deg (0..180), mass_min [kg], mass_max [kg],
//                   radius_min [m], radius_max [m] }
//   variants      [ { label (required, unique), drag, wind, air, contact, integrator } ]
//                   each section has the same keys as above; it starts from the scene's own
//                   section, so a variant need only name what differs.
//
// Omitted sections and fields take the Scene defaults (scene.hpp). At least one particle is
// required (from `particles`, `emitter`, or both). Unknown keys, duplicate keys, wrong types,
// non-finite numbers (1e400 overflows to infinity) and out-of-range values are errors; every one
// is reported with its JSON path. Saved files list every field, defaults included.
#include "io/preset_io.hpp"

#include "io/atomic_output.hpp"
#include "io/preset_parse.hpp"
#include "io/preset_reader.hpp"

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

PresetJson vec_json(const Vec3& v) { return PresetJson::array({v.x, v.y, v.z}); }

PresetJson air_json(const Air& a) { return {{"density", a.density_kg_m3}, {"viscosity", a.viscosity_pa_s}}; }

PresetJson wind_json(const WindSettings& w) {
    return {{"kind", to_string(w.kind)},
            {"velocity", vec_json(w.velocity)},
            {"amplitude", vec_json(w.gust_amplitude)},
            {"period", w.gust_period_s},
            {"seed", w.gust_seed},
            {"reference_height", w.reference_height_m},
            {"exponent", w.shear_exponent},
            {"center", vec_json(w.vortex_center)},
            {"axis", vec_json(w.vortex_axis)},
            {"max_speed", w.vortex_max_speed},
            {"core_radius", w.vortex_core_radius_m}};
}

PresetJson drag_json(const DragSettings& d) {
    // b is always written (null = Stokes from the air) so that a variant's drag section never
    // inherits the scene's b on reload.
    return {{"model", to_string(d.model)}, {"cd", d.cd}, {"b", d.linear_b ? PresetJson(*d.linear_b) : PresetJson(nullptr)}};
}

PresetJson contact_json(const ContactSettings& c) {
    return {{"restitution", c.restitution}, {"friction", c.friction}, {"rest_speed", c.rest_speed}};
}

PresetJson integrator_json(const IntegratorSettings& s) {
    return {{"method", to_string(s.method)}, {"dt", s.dt}, {"rtol", s.rtol}, {"atol", s.atol}, {"adaptive", s.adaptive}};
}

PresetJson particle_json(const ParticleSpec& p) {
    return {{"position", vec_json(p.position)}, {"velocity", vec_json(p.velocity)}, {"mass", p.mass}, {"radius", p.radius}};
}

PresetJson emitter_json(const Emitter& e) {
    return {{"count", static_cast<std::uint64_t>(e.count)},
            {"seed", e.seed},
            {"region_min", vec_json(e.region_min)},
            {"region_max", vec_json(e.region_max)},
            {"speed_min", e.speed_min},
            {"speed_max", e.speed_max},
            {"direction", vec_json(e.direction)},
            {"spread_deg", e.spread_deg},
            {"mass_min", e.mass_min},
            {"mass_max", e.mass_max},
            {"radius_min", e.radius_min},
            {"radius_max", e.radius_max}};
}

PresetJson variant_json(const Variant& v) {
    PresetJson j = {{"label", v.label}};
    if (v.drag) j["drag"] = drag_json(*v.drag);
    if (v.wind) j["wind"] = wind_json(*v.wind);
    if (v.air) j["air"] = air_json(*v.air);
    if (v.contact) j["contact"] = contact_json(*v.contact);
    if (v.integrator) j["integrator"] = integrator_json(*v.integrator);
    return j;
}

PresetJson scene_json(const Scene& s) {
    PresetJson j;
    j["format"] = "particle-lab-preset";
    j["version"] = 1;
    j["name"] = s.name;
    j["description"] = s.description;
    j["room"] = {{"center", vec_json(s.room.center)}, {"size", vec_json(s.room.size)}};
    j["world"] = {{"gravity", vec_json(s.world.gravity)}, {"air", air_json(s.world.air)}, {"wind", wind_json(s.world.wind)}};
    j["drag"] = drag_json(s.drag);
    j["contact"] = contact_json(s.contact);
    j["integrator"] = integrator_json(s.integrator);
    j["particles"] = PresetJson::array();
    for (const ParticleSpec& p : s.particles) j["particles"].push_back(particle_json(p));
    if (s.emitter) j["emitter"] = emitter_json(*s.emitter);
    j["variants"] = PresetJson::array();
    for (const Variant& v : s.variants) j["variants"].push_back(variant_json(v));
    return j;
}

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
    write_pretty(scene_json(scene), 0, out);
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
