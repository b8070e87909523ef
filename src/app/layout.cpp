#include "app/layout.hpp"

#include <algorithm>
#include <cmath>

namespace pl::app {

ShellLayout compute_layout(float width, float height, const PanelCollapse& collapsed, const LayoutMetrics& m) {
    ShellLayout l;
    const float w = std::max(width, 320.0f), h = std::max(height, 240.0f);
    // Fixed-width controls; narrow windows give up a little of it first.
    const float left_w = std::round(std::min(330.0f, 0.3f * w));
    const float right_w = std::round(0.4f * w);
    const float body_h = h - m.status_h;
    const float analysis_open_h = std::round(std::clamp(0.28f * h, 150.0f, 340.0f));
    const float analysis_h = collapsed.analysis ? m.title_bar_h : analysis_open_h;

    l.status = {0, body_h, w, m.status_h};
    l.controls = {0, 0, left_w, collapsed.controls ? m.title_bar_h : body_h};
    l.plots = {w - right_w, 0, right_w, collapsed.plots ? m.title_bar_h : body_h - analysis_h};
    l.toolbar = {left_w, 0, w - left_w - right_w, m.toolbar_h};

    const float view_left = collapsed.controls ? 0.0f : left_w;
    const float view_right = collapsed.plots ? w : w - right_w;
    const float view_bottom = body_h - analysis_h;
    l.view = {view_left, m.toolbar_h, view_right - view_left, std::max(view_bottom - m.toolbar_h, 1.0f)};
    l.analysis = {view_left, view_bottom, w - view_left, analysis_h};
    return l;
}

}  // namespace pl::app
