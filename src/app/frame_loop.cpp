#include "app/frame_loop.hpp"

#include "app/camera_store.hpp"
#include "app/config_dir.hpp"
#include "app/imgui_setup.hpp"
#include "app/input_events.hpp"
#include "app/layout.hpp"
#include "app/particle_tooltip.hpp"
#include "app/physics_driver.hpp"
#include "app/physics_thread.hpp"
#include "app/record_controls.hpp"
#include "app/scene_renderer.hpp"
#include "app/screenshot.hpp"
#include "app/session_requests.hpp"
#include "app/shell_windows.hpp"
#include "app/shortcuts.hpp"
#include "app/signals.hpp"
#include "app/measure_tool.hpp"
#include "app/state_dump.hpp"
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
constexpr double max_frame_dt_s = 0.25;     // the camera keys' longest move per frame (a dragged window, a debugger)
constexpr double default_max_fps = 120.0;  // without vsync (e.g. Xvfb), do not spin a core
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

// Steps on the frame loop's fixed clock (deterministic runs, recordings): exactly the steps
// `real_dt` owes, however long they take.
PhysicsStats step_on_fixed_clock(ui::LabSession& s, double real_dt, const AfterSteps& after_step) {
    PhysicsStats out;
    if (!s.experiment || s.paused) return out;
    const double t_before = s.experiment->time();
    const FrameAdvance advance = advance_frame(*s.experiment, real_dt, s.time_scale, 0.0, after_step);
    out = {advance.steps, s.experiment->time() - t_before, advance.physics_ms, advance.behind};
    return out;
}

// What the status bar shows about this frame's physics (`real_dt`: the real time it stood for).
void show_physics_stats(ui::FrameStats& f, const PhysicsStats& p, double real_dt) {
    f.substeps = p.steps;
    f.behind = p.behind;
    f.physics_ms = p.physics_ms;
    smooth(f.real_time_factor, p.simulated_s / std::max(real_dt, 1e-9), real_dt);
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
        area = to_pixels(crop->crop_x, crop->crop_y, crop->crop_w, crop->crop_h, sx, sy);
    }
    const std::string error = write_screenshot_png(file, w, h, area);
    if (error.empty()) {
        s.status_message = "Saved " + file.string();
    } else {
        std::fprintf(stderr, "particle-lab: %s\n", error.c_str());
        s.error_popup = error;
    }
}

// The GUI's state across frames. Members are destroyed in reverse order: the physics thread
// (last) stops before anything it touches goes away.
class FrameLoop {
public:
    FrameLoop(ui::LabSession& session, const GuiOptions& options)
        : session_(session), options_(options), config_(user_config_dir()),
          window_(default_width, default_height, window_title(session)), title_(window_title(session)) {
        // Our key callback first: ImGui's backend chains to the callback installed before it.
        install_key_queue(window_.handle(), &input_);
        imgui_.emplace(window_.handle(), config_);
        renderer_.emplace();
        install_signal_handlers();
        if (deterministic()) glfwSwapInterval(0);
        view_.room = session.experiment->scene().room;
        if (config_) view_.file = *config_ / "camera.txt";
        view_.camera = (view_.file ? load_camera(*view_.file, view_.room) : std::nullopt).value_or(framing_camera(view_.room));
        if (options.record) {
            record_.next = *options.record;
            record_.quit_when_done = record_.toggle = true;
        }
        // A --record run is on the fixed clock from its first step: the thread must not step
        // before the first frame switches it off, or two recordings would start apart.
        physics_ = std::make_unique<PhysicsThread>(session_, before_steps_, after_steps_,
                                                   !deterministic() && !options.record);
    }

    // One frame; false when the loop ends.
    bool frame();

    int finish() {
        physics_.reset();  // no more steps: what follows reads a still session
        finish_recording(record_, session_);
        if (view_.file) save_camera(*view_.file, view_.camera, view_.room);
        dump_state(options_, session_, frames_, snapshot());
        // --record that could not record (no ffmpeg, an unwritable folder) is a failed run.
        return options_.record && !record_.error.empty() ? 1 : 0;
    }

private:
    bool deterministic() const { return options_.fixed_frame_dt.has_value(); }
    ViewSnapshot snapshot() const { return {view_.camera, shown_panes_, drag_.aim, &record_}; }
    // Everything that reads or edits the session, under the physics mutex. Returns whether this
    // is the last frame.
    // `frame_dt`: the real time since the last frame.
    bool session_frame(bool quitting, double frame_dt);
    void draw(const ShellLayout& layout, const FramebufferMapping& fb);
    void present();

    ui::LabSession& session_;
    const GuiOptions& options_;
    std::optional<std::filesystem::path> config_;
    AppWindow window_;
    InputQueue input_;
    std::optional<ImGuiLayer> imgui_;      // after the key queue (see the constructor)
    std::optional<SceneRenderer> renderer_;  // needs the GL context ImGuiLayer sets up
    CameraState view_;
    TrailHistory trails_;
    // After each group of base steps: trails, and the live metrics, which need every step.
    const AfterSteps after_steps_ = [this]() -> std::uint64_t {
        if (!session_.experiment) return 1;
        trails_.sample(*session_.experiment, static_cast<std::size_t>(std::max(session_.selected_particle, 0)),
                       static_cast<std::size_t>(std::max(session_.trail_particles, 0)));
        return std::min(ui::record_step(session_), trails_.steps_until_due(*session_.experiment));
    };
    const std::function<void()> before_steps_ = [this] { trails_.sync(session_.experiment.get()); };
    PanelCollapse collapsed_;
    ViewDrag drag_;
    std::string title_;
    long frames_ = 0;
    int fb_w_ = 0, fb_h_ = 0;  // the framebuffer size of this frame: draw() plans for it, present() draws at it
    bool drawn_ = true;        // present() has run since the last draw()
    std::vector<ViewPane> shown_panes_;  // the last frame's, for the state dump
    RecordControl record_;
    Clock::time_point last_ = Clock::now();
    std::unique_ptr<PhysicsThread> physics_;
};

bool FrameLoop::session_frame(bool quitting, double frame_dt) {
    ui::LabSession& session = session_;
    if (glfwWindowShouldClose(window_.handle())) {
        glfwSetWindowShouldClose(window_.handle(), GLFW_FALSE);
        session.request({ui::PendingAction::Kind::quit, {}});
    }
    imgui_->begin_frame();
    const ImGuiIO& io = ImGui::GetIO();
    const ViewCommand key_command = apply_shortcuts(input_.keys, io.WantTextInput, io.WantCaptureKeyboard, session);
    if (key_command.cancel_gesture) cancel_launch_aim(drag_.aim);
    if (key_command.toggle_recording) record_.toggle = true;
    apply_view_command(key_command, view_, session);
    input_.keys.clear();
    glfwGetFramebufferSize(window_.handle(), &fb_w_, &fb_h_);
    const FramebufferMapping fb{io.DisplaySize.x > 0 ? static_cast<float>(fb_w_) / io.DisplaySize.x : 1.0f,
                                io.DisplaySize.y > 0 ? static_cast<float>(fb_h_) / io.DisplaySize.y : 1.0f, fb_h_};
    const ShellLayout layout = compute_layout(io.DisplaySize.x, io.DisplaySize.y, collapsed_, layout_metrics());
    begin_record_frame(record_, session, layout, io.DisplaySize.x, io.DisplaySize.y, fb.scale_x, fb.scale_y);
    // A recording runs on its own fixed clock: each frame is 1/fps of real time, however long it
    // takes; so do deterministic runs. Otherwise the physics thread follows real time.
    const std::optional<double> record_dt = record_.recorder.frame_dt();
    const std::optional<double> fixed_dt = record_dt ? record_dt : options_.fixed_frame_dt;
    physics_->set_real_time(!fixed_dt);
    const double camera_dt = fixed_dt.value_or(std::min(frame_dt, max_frame_dt_s));
    handle_view_keys(window_.handle(), input_, view_.camera, static_cast<float>(camera_dt));

    // The requests before this frame's steps: a reset must not be followed by steps from the old state.
    trails_.sync(session.experiment.get());
    if (perform_state_requests(session, after_steps_).state_jumped) trails_.clear();
    const PhysicsStats stepped = fixed_dt ? step_on_fixed_clock(session, *fixed_dt, after_steps_) : physics_->take_stats();
    show_physics_stats(session.frame, stepped, fixed_dt.value_or(frame_dt));
    ui::record_frame(session);
    follow_room(view_, session);

    draw(layout, fb);
    // Pixels read back this frame (a recording, a screenshot) need the scene drawn first; any
    // other frame draws it after the mutex is released (FrameLoop::frame).
    if (record_.recorder.active() || session.requests.screenshot || options_.screenshot) present();
    ++frames_;
    const bool record_over = end_record_frame(record_, session, fb_w_, fb_h_);
    const bool last_frame = quitting || record_over || (options_.frames && frames_ >= *options_.frames);
    if (session.requests.screenshot) {
        take_screenshot(session.requests.screenshot_path, window_.handle(), session, &session.requests);
        session.requests.screenshot = false;
        session.requests.crop_w = session.requests.crop_h = 0.0f;
    }
    if (last_frame && options_.screenshot) take_screenshot(*options_.screenshot, window_.handle(), session, nullptr);
    // Dumped once the frame is complete, so what it says agrees with itself: a preset loaded by
    // Enter in the path field and the keyboard that field gave back (ImGui's WantTextInput is
    // set when the frame after the Enter starts).
    if (take_dump_request()) dump_state(options_, session, frames_, snapshot());
    if (const std::string t = window_title(session); t != title_) {
        title_ = t;
        glfwSetWindowTitle(window_.handle(), title_.c_str());
    }
    return last_frame;
}

// Panels, then the 3D view's overlays and input (the view is the space between panels), and
// what the scene's GL calls will need: everything that reads the session, none of the drawing.
void FrameLoop::draw(const ShellLayout& layout, const FramebufferMapping& fb) {
    ui::LabSession& session = session_;
    apply_view_command(draw_shell_windows(session, layout, collapsed_, record_), view_, session);
    const std::size_t variant_count = session.experiment ? session.experiment->variant_count() : 1;
    const std::vector<ViewPane> panes = view_panes(layout.view, session.split_view, variant_count,
                                                   split_variants(session.split_variants, variant_count));
    const std::optional<HoveredParticle> hovered = handle_view_mouse(drag_, view_.camera, panes, session);
    if (drag_.clicked && session.measuring) measure_click(session, trails_, panes, view_.camera, drag_.press_x, drag_.press_y);
    draw_view_overlay(session, panes, view_.camera, hovered);
    draw_measure_overlay(session, panes, view_.camera);
    draw_launch_aim(drag_.aim, session, panes, view_.camera);
    if (hovered) show_particle_tooltip(session, hovered->particle);
    ui::draw_popups(session);

    renderer_->prepare(session, trails_, panes, view_.camera, fb);
    shown_panes_ = panes;
    drawn_ = false;
}

// The scene and ImGui's draw lists, from what draw() kept: no session state, so it runs without
// the physics thread's mutex (a software rasteriser spends milliseconds in its draw calls).
void FrameLoop::present() {
    if (drawn_) return;
    drawn_ = true;
    glViewport(0, 0, fb_w_, fb_h_);
    glClearColor(0.085f, 0.093f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer_->submit();
    imgui_->render();
}

bool FrameLoop::frame() {
    glfwPollEvents();
    // Quitting still draws this one frame when a screenshot of the last frame is wanted.
    const bool quitting = quit_signalled() || session_.requests.quit;
    if (quitting && !options_.screenshot) return false;
    const Clock::time_point start = Clock::now();
    const double frame_dt = std::chrono::duration<double>(start - last_).count();
    last_ = start;
    // The status bar's own numbers: the physics thread never reads them.
    smooth(session_.frame.fps, 1.0 / std::max(frame_dt, 1e-6), frame_dt);

    bool last_frame = false;
    double waited_s = 0.0;  // for the physics thread's slice: not the UI's own time
    {
        const Clock::time_point asked = Clock::now();
        const std::unique_lock<std::mutex> lock = physics_->lock_for_ui();
        waited_s = std::chrono::duration<double>(Clock::now() - asked).count();
        last_frame = session_frame(quitting, frame_dt);
    }
    // Drawing and presenting (where a software rasteriser does its work) run without the mutex.
    present();
    glfwSwapBuffers(window_.handle());
    const double spent = std::chrono::duration<double>(Clock::now() - start).count();
    session_.frame.render_ms = 1e3 * (spent - waited_s);  // shown by the next frame's status bar
    if (last_frame) return false;
    const double cap_s = 1.0 / options_.max_fps.value_or(default_max_fps);
    if (!deterministic() && !record_.recorder.active() && spent < cap_s)
        std::this_thread::sleep_for(std::chrono::duration<double>(cap_s - spent));
    return true;
}

}  // namespace

int run_frame_loop(ui::LabSession& session, const GuiOptions& options) {
    FrameLoop loop(session, options);
    while (loop.frame()) {
    }
    return loop.finish();
}

}  // namespace pl::app
