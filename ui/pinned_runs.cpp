#include "ui/pinned_runs.hpp"

#include "ui/frame_recorder.hpp"
#include "ui/lab_session.hpp"
#include "ui/sections.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace pl::ui {
namespace {

std::string number(double v, const char* unit = "") { return fmt::format("{:.4g}{}", v, unit); }

std::string vector3(const Vec3& v, const char* unit) { return fmt::format("({:.3g}, {:.3g}, {:.3g}){}", v.x, v.y, v.z, unit); }

template <class Track>
void thin(Track& track) {
    for (SampleSeries* series : track.all()) series->set_capacity(PinBoard::max_samples);
}

std::string first_label(const LabSession& s, std::size_t variant) {
    return s.experiment->variant_count() > 1 ? variant_name(s, variant) : s.scene.name;
}

}  // namespace

std::vector<RunSetting> run_settings(const Model& m, const ParticleSpec& p0, const Vec3& launch_velocity) {
    std::vector<RunSetting> out{{"drag", to_string(m.drag.model)}};
    if (m.drag.model == DragModel::quadratic) out.push_back({"Cd", number(m.drag.cd)});
    if (m.drag.model == DragModel::linear)
        out.push_back({"b", m.drag.linear_b ? number(*m.drag.linear_b, " N s/m") : std::string("Stokes")});
    out.push_back({"wind", to_string(m.world.wind.kind)});
    if (m.world.wind.kind != WindKind::none) out.push_back({"wind velocity", vector3(m.world.wind.velocity, " m/s")});
    if (m.world.air.model == AirModel::isa) {
        out.push_back({"air", "ISA"});
        out.push_back({"floor altitude", number(m.world.air.base_altitude_m, " m")});
    } else {
        out.push_back({"air density", number(m.world.air.density_kg_m3, " kg/m3")});
        out.push_back({"air viscosity", number(m.world.air.viscosity_pa_s, " Pa s")});
    }
    if (m.world.buoyancy) out.push_back({"buoyancy", "on"});
    if (m.world.added_mass) out.push_back({"added mass", "on"});
    out.push_back({"e", number(m.contact.restitution)});
    out.push_back({"mu", number(m.contact.friction)});
    out.push_back({"rest speed", number(m.contact.rest_speed, " m/s")});
    out.push_back({"method", to_string(m.integrator.method)});
    out.push_back({"dt", number(m.integrator.dt, " s")});
    out.push_back({"g", vector3(m.world.gravity, " m/s2")});
    out.push_back({"mass", number(p0.mass, " kg")});
    out.push_back({"radius", number(p0.radius, " m")});
    out.push_back({"start", vector3(p0.position, " m")});
    out.push_back({"v0", vector3(launch_velocity, " m/s")});
    return out;
}

std::string settings_difference(const std::vector<RunSetting>& before, const std::vector<RunSetting>& now,
                                std::size_t max_shown) {
    std::vector<std::string> changed;
    for (const RunSetting& n : now) {
        const auto old = std::find_if(before.begin(), before.end(), [&](const RunSetting& b) { return b.name == n.name; });
        if (old == before.end() || old->value != n.value) changed.push_back(n.name + " " + n.value);
    }
    std::string out;
    for (std::size_t k = 0; k < changed.size() && k < max_shown; ++k) out += (k ? ", " : "") + changed[k];
    if (changed.size() > max_shown) out += ", ...";
    return out;
}

PinBoard& pins_of(LabSession& s) {
    if (!s.pins) s.pins = std::make_shared<PinBoard>();
    return *s.pins;
}

const PinBoard* pins_if_any(const LabSession& s) { return s.pins.get(); }

std::string pin_current_run(LabSession& s) {
    if (!s.experiment || s.experiment->variant_count() == 0) return "Nothing to pin";
    PlotHistory& h = history_of(s);
    const std::size_t v = std::min(static_cast<std::size_t>(std::max(s.selected_variant, 0)), h.variants.size() - 1);
    const Simulation& sim = s.experiment->run(v);
    PinBoard& board = pins_of(s);
    PinnedRun pin;
    pin.number = board.next_number++;
    pin.settings = run_settings(sim.model(), first_particle(s.experiment->scene()).value_or(ParticleSpec{}), h.launch_velocity);
    const std::string difference = board.runs.empty() ? first_label(s, v) : settings_difference(board.runs.back().settings, pin.settings);
    pin.label = "run " + std::to_string(pin.number) + ": " + (difference.empty() ? "same settings" : difference);
    pin.t_end = sim.time();
    pin.particles = h.variants[v].particles;
    for (ParticleTrack& t : pin.particles) thin(t);
    if (h.aggregated()) {
        pin.aggregate = h.variants[v].aggregate;
        thin(pin.aggregate);
    }
    pin.paths = h.variants[v].paths;
    if (v < h.trackers.size()) pin.metrics = metrics_of(h.trackers[v], sim);
    std::string note;
    if (board.runs.size() == PinBoard::max_pins) {
        note = " (unpinned " + board.runs.front().label.substr(0, board.runs.front().label.find(':')) + ")";
        board.runs.erase(board.runs.begin());
    }
    board.runs.push_back(std::move(pin));
    return "Pinned " + board.runs.back().label + note;
}

void unpin(LabSession& s, int number) {
    std::vector<PinnedRun>& runs = pins_of(s).runs;
    runs.erase(std::remove_if(runs.begin(), runs.end(), [&](const PinnedRun& r) { return r.number == number; }), runs.end());
}

void clear_pins(LabSession& s) { pins_of(s).runs.clear(); }

Rgba pin_color(int number, float alpha) {
    Rgba c = series_color(10 + number);
    c[3] = alpha;
    return c;
}

}  // namespace pl::ui
