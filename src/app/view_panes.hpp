// The 3D view as one pane (all variants overlaid) or split into side-by-side panes, one per
// variant (up to four), all seen through the same camera.
#pragma once

#include "app/layout.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace pl::app {

constexpr std::size_t max_split_panes = 4;

struct ViewPane {
    Rect rect;                           // ImGui (window) coordinates
    std::optional<std::size_t> variant;  // empty: every variant
};

std::vector<ViewPane> view_panes(const Rect& view, bool split, std::size_t variant_count);

}  // namespace pl::app
