// Reads one JSON value of a preset field as its row (physics/model/field_schema.hpp) says, and
// reports what is wrong with it at its JSON path. Internal to the preset reader.
#pragma once

#include "io/preset_reader.hpp"
#include "physics/model/field_schema.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace pl {

std::string number_text(double x);
std::string vec_text(const Vec3& v);
// "number", "boolean", "string", "array", "object" or "null".
std::string type_text(const PresetJson& v);

// Every function reports what is wrong and returns whether it wrote a usable value to `out`;
// on failure `out` is left as it was.
class ValueReader {
public:
    explicit ValueReader(PresetErrorList& errors) : errors_(errors) {}

    void fail(const std::string& path, std::string message) { errors_.add(path, std::move(message)); }

    bool number(const PresetJson& v, const std::string& path, double& out, const schema::Bounds& b);
    bool vec3(const PresetJson& v, const std::string& path, Vec3& out, const schema::Bounds& b);
    bool bounded_vec3(const PresetJson& v, const std::string& path, Vec3& out, double max_length);
    bool direction(const PresetJson& v, const std::string& path, Vec3& out, const schema::Bounds& b);
    bool unsigned_integer(const PresetJson& v, const std::string& path, std::uint64_t& out, std::uint64_t max);
    bool string(const PresetJson& v, const std::string& path, std::string& out, bool non_empty = false);
    bool boolean(const PresetJson& v, const std::string& path, bool& out);
    bool enumeration(const PresetJson& v, const std::string& path, int& out, const schema::EnumNames& names);
    // null: absent (reset); otherwise a number within `b`.
    bool optional_number(const PresetJson& v, const std::string& path, std::optional<double>& out, const schema::Bounds& b);
    bool format_tag(const PresetJson& v, const std::string& path);
    bool version_tag(const PresetJson& v, const std::string& path);

private:
    PresetErrorList& errors_;
};

// "a, b, c": the names of an enumeration, as messages and the format reference list them.
std::string enum_names_text(const schema::EnumNames& names);

}  // namespace pl
