#include "ui/scene_validation.hpp"

#include "io/preset_io.hpp"

namespace pl::ui {

std::string scene_errors(const Scene& scene) {
    const LoadResult r = parse_preset(serialize_preset(scene));
    return r.ok() ? std::string{} : r.error_text();
}

}  // namespace pl::ui
