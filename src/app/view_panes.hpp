// The 3D view as one pane (all variants overlaid) or split into side-by-side panes, one per
// variant (up to nine, chosen by the user), all seen through the same camera.
#pragma once

#include "app/layout.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace pl::app {

constexpr std::size_t max_split_panes = 9;

struct ViewPane {
    Rect rect;                           // ImGui (window) coordinates
    std::optional<std::size_t> variant;  // empty: every variant
};

// The variants the split view shows: the user's choice (LabSession::split_variants) among those
// that exist, or the first max_split_panes when there is none.
std::vector<std::size_t> split_variants(const std::vector<int>& chosen, std::size_t variant_count);

// One pane, or one per variant of `shown` in a grid that suits the view's shape.
std::vector<ViewPane> view_panes(const Rect& view, bool split, std::size_t variant_count, const std::vector<std::size_t>& shown);

}  // namespace pl::app
