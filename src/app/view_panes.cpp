#include "app/view_panes.hpp"

#include <algorithm>

namespace pl::app {

std::vector<ViewPane> view_panes(const Rect& view, bool split, std::size_t variant_count) {
    if (!split || variant_count < 2) return {{view, std::nullopt}};
    const std::size_t n = std::min(variant_count, max_split_panes);
    // Columns for wide views, rows for tall ones, a 2 x 2 grid for four.
    std::size_t cols = n, rows = 1;
    if (n == 4) cols = rows = 2;
    else if (view.h > view.w) std::swap(cols, rows);
    constexpr float gap = 2.0f;
    const float w = (view.w - gap * static_cast<float>(cols - 1)) / static_cast<float>(cols);
    const float h = (view.h - gap * static_cast<float>(rows - 1)) / static_cast<float>(rows);
    std::vector<ViewPane> panes;
    for (std::size_t v = 0; v < n; ++v) {
        const std::size_t col = v % cols, row = v / cols;
        panes.push_back({{view.x + static_cast<float>(col) * (w + gap), view.y + static_cast<float>(row) * (h + gap), w, h}, v});
    }
    return panes;
}

}  // namespace pl::app
