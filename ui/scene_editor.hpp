// Editing the scene from the panels: every change is made on a copy, checked against the preset
// rules (scene_validation.hpp), and only then applied (LabSession::apply_scene, dirty = true).
#pragma once

#include "ui/lab_session.hpp"
#include "physics/model/field_schema.hpp"
#include "ui/panel_state.hpp"

#include <functional>

namespace pl::ui {

class SceneEditor {
public:
    explicit SceneEditor(LabSession& s);

    const Scene& scene() const { return s_.scene; }
    // For reading a section through an `at` accessor; edit only through the methods below.
    Scene& current() { return s_.scene; }

    // A number field; `set(copy, value)` writes the edited value into a copy of the scene.
    void number(const char* label, double value, const std::function<void(Scene&, double)>& set,
                const char* format = "%.6g", const char* help = nullptr);
    void vec3(const char* label, const Vec3& value, const std::function<void(Scene&, const Vec3&)>& set,
              const char* format = "%.4g", const char* help = nullptr);
    // A whole number >= 0; its upper bound is the preset row's, checked with the other rules.
    void integer(const char* label, std::uint64_t value, const std::function<void(Scene&, std::uint64_t)>& set,
                 const char* help = nullptr);
    // A text field, applied when the user leaves it.
    void text(const char* label, const std::string& value, const std::function<void(Scene&, const std::string&)>& set);
    // Any other change (combo, checkbox, button); a refusal opens the error dialog.
    bool apply(const std::function<void(Scene&)>& change);

private:
    bool commit(const std::function<void(Scene&)>& change, bool from_field);

    LabSession& s_;
    PanelState& panels_;
};

// The fields of a section, from its preset rows (physics/model/schema/): label, unit, tooltip
// (help and bounds) and, where the section has an enumeration, only the fields it applies to.
// `at` finds the section inside a scene. Instantiated for Scene (name, description), Room, World
// (gravity), ParticleSpec, Emitter, Variant (label), IntegratorSettings, CollisionSettings and the
// sections below.
template <class S>
void edit_fields(SceneEditor& ed, const std::function<S&(Scene&)>& at);
// One row of a section.
template <class S>
void edit_field(SceneEditor& ed, const schema::Field<S>& field, const std::function<S&(Scene&)>& at);

// The section editors, shared by the scene and by a variant's overrides: `at` finds the section
// inside a scene (the base scene's, or a variant's override).
void edit_drag_section(SceneEditor& ed, const std::function<DragSettings&(Scene&)>& at);
void edit_wind_section(SceneEditor& ed, const std::function<WindSettings&(Scene&)>& at, bool drag_on);
void edit_air_section(SceneEditor& ed, const std::function<Air&(Scene&)>& at);
void edit_contact_section(SceneEditor& ed, const std::function<ContactSettings&(Scene&)>& at);
void edit_integrator_section(SceneEditor& ed, const std::function<IntegratorSettings&(Scene&)>& at);

}  // namespace pl::ui
