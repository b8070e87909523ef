#include "app/frame_loop.hpp"

#include "app/camera_store.hpp"
#include "app/config_dir.hpp"
#include "app/imgui_setup.hpp"
#include "app/input_events.hpp"
#include "app/layout.hpp"
#include "app/particle_tooltip.hpp"
#include "app/physics_driver.hpp"
#include "app/scene_renderer.hpp"
#include "app/screenshot.hpp"
#include "app/session_requests.hpp"
#include "app/shell_windows.hpp"
#include "app/shortcuts.hpp"
#include "app/signals.hpp"
#include "app/state_dump.hpp"
#include "app/measure_tool.hpp"
#include "app/trail_history.hpp"
#include "app/view_input.hpp"
#include "app/view_overlay.hpp"
#include "app/view_panes.hpp"
#include "app/window.hpp"
#include "ui/lab_ui.hpp"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <thread>

namespace pl::app {

namespace {

constexpr int default_width = 1600, default_height = 900;
constexpr double physics_budget_s = 0.008;  // wall time per frame the physics may use
constexpr double max_frame_dt_s = 0.25;     // longer gaps (a dragged window, a debugger) are not caught up
constexpr double frame_cap_s = 1.0 / 120.0;  // without vsync (e.g. Xvfb), do not spin a core
constexpr double stats_smoothing_s = 0.5;   // time constant of the FPS and real-time-factor averages

using Clock = std::chrono::steady_clock;

std::string window_title(const ui::LabSession& s) {
    std::string title = "particle-lab - " + s.scene.name;
    if (s.dirty) title += " *";
    return title;
}

struct CameraState {
    OrbitCamera camera;
    Room room;  // the room the camera was set up for
    std::optional<std::filesystem::path> file;
};

void apply_view_command(const ViewCommand& cmd, CameraState& c, const ui::LabSession& s) {
    if (cmd.reset) c.camera = framing_camera(c.room);
    if (cmd.axis) c.camera = axis_camera(c.room, *cmd.axis, cmd.from_negative);
    if (cmd.focus_selected && s.experiment) {
        const auto v = static_cast<std::size_t>(std::max(s.selected_variant, 0));
        const auto i = static_cast<std::size_t>(std::max(s.selected_particle, 0));
        if (v < s.experiment->variant_count() && i < s.experiment->run(v).particle_count())
            c.camera.target = glm::vec3(s.experiment->run(v).state().position(i));
    }
}

// A newly loaded preset with a different room gets a camera that frames it.
void follow_room(CameraState& c, const ui::LabSession& s) {
    if (!s.experiment) return;
    const Room& room = s.experiment->scene().room;
    if (room.center == c.room.center && room.size == c.room.size) return;
    c.room = room;
    c.camera = framing_camera(room);
}

void smooth(double& average, double sample, double dt) {
    const double a = 1.0 - std::exp(-dt / stats_smoothing_s);
    average = average == 0.0 ? sample : average + a * (sample - average);
}

// This frame's steps (after the requests: a reset must not be followed by steps from the old
// state) and what the status bar shows about them.
void run_physics(ui::LabSession& s, double real_dt, double budget_s, const AfterSteps& after_step) {
    FrameAdvance advance;
    double simulated = 0.0;
    if (s.experiment && !s.paused) {
        const double t_before = s.experiment->time();
        advance = advance_frame(*s.experiment, real_dt, s.time_scale, budget_s, after_step);
        simulated = s.experiment->time() - t_before;
    }
    s.frame.substeps = advance.steps;
    s.frame.behind = advance.behind;
    s.frame.physics_ms = advance.physics_ms;
    smooth(s.frame.real_time_factor, simulated / std::max(real_dt, 1e-9), real_dt);
}

void dump_state(const GuiOptions& o, const ui::LabSession& s, long frames, const ViewSnapshot& view) {
    if (!o.dump_state) return;
    const std::string error = write_state_dump(*o.dump_state, s, frames, view);
    if (!error.empty()) std::fprintf(stderr, "particle-lab: --dump-state: %s\n", error.c_str());
}

// The whole window, or the crop (in ImGui coordinates) a panel asked for.
void take_screenshot(const std::filesystem::path& file, GLFWwindow* window, ui::LabSession& s, const ui::Requests* crop) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    PixelRect area{0, 0, w, h};
    if (crop && crop->crop_w > 0.0f && crop->crop_h > 0.0f) {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        const float sx = display.x > 0 ? static_cast<float>(w) / display.x : 1.0f;
        const float sy = display.y > 0 ? static_cast<float>(h) / display.y : 1.0f;
        area = {static_cast<int>(std::lround(crop->crop_x * sx)), static_cast<int>(std::lround(crop->crop_y * sy)),
                static_cast<int>(std::lround(crop->crop_w * sx)), static_cast<int>(std::lround(crop->crop_h * sy))};
    }
    const std::string error = write_screenshot_png(file, w, h, area);
    if (error.empty()) {
        s.status_message = "Saved " + file.string();
    } else {
        std::fprintf(stderr, "particle-lab: %s\n", error.c_str());
        s.error_popup = error;
    }
}

}  // namespace

int run_frame_loop(ui::LabSession& session, const GuiOptions& options) {
    const std::optional<std::filesystem::path> config = user_config_dir();
    AppWindow window(default_width, default_height, window_title(session));
    InputQueue input;
    install_key_queue(window.handle(), &input);
    install_signal_handlers();
    ImGuiLayer imgui(window.handle(), config);
    SceneRenderer renderer;
    const bool deterministic = options.fixed_frame_dt.has_value();
    if (deterministic) glfwSwapInterval(0);

    CameraState view;
    view.room = session.experiment->scene().room;
    if (config) view.file = *config / "camera.txt";
    view.camera = (view.file ? load_camera(*view.file, view.room) : std::nullopt).value_or(framing_camera(view.room));

    TrailHistory trails;
    // After each group of base steps: trails, and the live metrics, which need every step.
    const AfterSteps after_steps = [&]() -> std::uint64_t {
        if (!session.experiment) return 1;
        trails.sample(*session.experiment, static_cast<std::size_t>(std::max(session.selected_particle, 0)),
                      static_cast<std::size_t>(std::max(session.trail_particles, 0)));
        return std::min(ui::record_step(session), trails.steps_until_due(*session.experiment));
    };
    PanelCollapse collapsed;
    ViewDrag drag;
    std::string title = window_title(session);
    long frames = 0;
    std::vector<ViewPane> shown_panes;  // the last frame's, for the state dump
    Clock::time_point last = Clock::now();

    while (true) {
        glfwPollEvents();
        // Quitting still draws this one frame when a screenshot of the last frame is wanted.
        const bool quitting = quit_signalled() || session.requests.quit;
        if (quitting && !options.screenshot) break;
        if (take_dump_request()) dump_state(options, session, frames, {view.camera, shown_panes, drag.aim});
        if (glfwWindowShouldClose(window.handle())) {
            glfwSetWindowShouldClose(window.handle(), GLFW_FALSE);
            session.request({ui::PendingAction::Kind::quit, {}});
        }
        const Clock::time_point now = Clock::now();
        const double measured_dt = std::chrono::duration<double>(now - last).count();
        last = now;
        const double real_dt = deterministic ? *options.fixed_frame_dt : std::min(measured_dt, max_frame_dt_s);

        imgui.begin_frame();
        const ImGuiIO& io = ImGui::GetIO();
        const ViewCommand key_command = apply_shortcuts(input.keys, io.WantTextInput, io.WantCaptureKeyboard, session);
        if (key_command.cancel_gesture) cancel_launch_aim(drag.aim);
        apply_view_command(key_command, view, session);
        input.keys.clear();
        handle_view_keys(window.handle(), input, view.camera, static_cast<float>(real_dt));

        trails.sync(session.experiment.get());
        if (perform_state_requests(session, after_steps).state_jumped) trails.clear();
        run_physics(session, real_dt, deterministic ? 0.0 : physics_budget_s, after_steps);
        smooth(session.frame.fps, 1.0 / std::max(measured_dt, 1e-6), measured_dt);
        ui::record_frame(session);
        follow_room(view, session);

        // Panels, then the 3D view's overlays and input (the view is the space between panels).
        const ShellLayout layout = compute_layout(io.DisplaySize.x, io.DisplaySize.y, collapsed, layout_metrics());
        apply_view_command(draw_shell_windows(session, layout, collapsed), view, session);
        const std::size_t variant_count = session.experiment ? session.experiment->variant_count() : 1;
        const std::vector<ViewPane> panes = view_panes(layout.view, session.split_view, variant_count,
                                                       split_variants(session.split_variants, variant_count));
        const std::optional<HoveredParticle> hovered = handle_view_mouse(drag, view.camera, panes, session);
        if (drag.clicked && session.measuring) measure_click(session, trails, panes, view.camera, drag.press_x, drag.press_y);
        draw_view_overlay(session, panes, view.camera, hovered);
        draw_measure_overlay(session, panes, view.camera);
        draw_launch_aim(drag.aim, session, panes, view.camera);
        if (hovered) show_particle_tooltip(session, hovered->particle);
        ui::draw_popups(session);

        int fb_w = 0, fb_h = 0;
        glfwGetFramebufferSize(window.handle(), &fb_w, &fb_h);
        glViewport(0, 0, fb_w, fb_h);
        glClearColor(0.085f, 0.093f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const FramebufferMapping fb{io.DisplaySize.x > 0 ? static_cast<float>(fb_w) / io.DisplaySize.x : 1.0f,
                                    io.DisplaySize.y > 0 ? static_cast<float>(fb_h) / io.DisplaySize.y : 1.0f, fb_h};
        renderer.draw(session, trails, panes, view.camera, fb);
        shown_panes = panes;
        imgui.render();

        ++frames;
        const bool last_frame = quitting || (options.frames && frames >= *options.frames);
        if (session.requests.screenshot) {
            take_screenshot(session.requests.screenshot_path, window.handle(), session, &session.requests);
            session.requests.screenshot = false;
            session.requests.crop_w = session.requests.crop_h = 0.0f;
        }
        if (last_frame && options.screenshot) take_screenshot(*options.screenshot, window.handle(), session, nullptr);
        glfwSwapBuffers(window.handle());
        if (last_frame) break;

        if (const std::string t = window_title(session); t != title) {
            title = t;
            glfwSetWindowTitle(window.handle(), title.c_str());
        }
        if (!deterministic) {
            const double spent = std::chrono::duration<double>(Clock::now() - now).count();
            if (spent < frame_cap_s) std::this_thread::sleep_for(std::chrono::duration<double>(frame_cap_s - spent));
        }
    }
    if (view.file) save_camera(*view.file, view.camera, view.room);
    dump_state(options, session, frames, {view.camera, shown_panes, drag.aim});
    return 0;
}

}  // namespace pl::app
