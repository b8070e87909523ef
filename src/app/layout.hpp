// The fixed layout, recomputed from the window size every frame:
//
//   +-----------+------- view toolbar -------+-----------------+
//   |           |                            |                 |
//   | controls  |          3D view           |     plots       |
//   |  ~330 px  |                            |   ~40% width    |
//   |           +----------------------------+-----------------+
//   |           |        analysis strip (collapsible)          |
//   +-----------+----------------------------------------------+
//   |                      status bar                          |
//   +----------------------------------------------------------+
//
// A collapsed panel keeps only its title bar and the 3D view takes the space it frees.
#pragma once

namespace pl::app {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    float right() const { return x + w; }
    float bottom() const { return y + h; }
    bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

struct PanelCollapse {
    bool controls = false, plots = false, analysis = false;
};

struct LayoutMetrics {
    float title_bar_h = 21.0f;  // a collapsed window's height
    float toolbar_h = 30.0f;
    float status_h = 26.0f;
};

struct ShellLayout {
    Rect controls, toolbar, view, plots, analysis, status;
};

ShellLayout compute_layout(float width, float height, const PanelCollapse& collapsed, const LayoutMetrics& m);

}  // namespace pl::app
