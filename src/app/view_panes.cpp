#include "app/view_panes.hpp"

#include <algorithm>
#include <cmath>

namespace pl::app {

std::vector<std::size_t> split_variants(const std::vector<int>& chosen, std::size_t variant_count) {
    std::vector<std::size_t> out;
    for (int v : chosen)
        if (v >= 0 && static_cast<std::size_t>(v) < variant_count && out.size() < max_split_panes &&
            std::find(out.begin(), out.end(), static_cast<std::size_t>(v)) == out.end())
            out.push_back(static_cast<std::size_t>(v));
    if (out.empty())
        for (std::size_t v = 0; v < std::min(variant_count, max_split_panes); ++v) out.push_back(v);
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<ViewPane> view_panes(const Rect& view, bool split, std::size_t variant_count, const std::vector<std::size_t>& shown) {
    if (!split || variant_count < 2 || shown.empty()) return {{view, std::nullopt}};
    const std::size_t n = shown.size();
    // Up to three in a row (a column in a tall view); more in a near-square grid.
    std::size_t cols = n <= 3 ? n : static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    std::size_t rows = (n + cols - 1) / cols;
    if (view.h > view.w) std::swap(cols, rows);
    constexpr float gap = 2.0f;
    const float w = (view.w - gap * static_cast<float>(cols - 1)) / static_cast<float>(cols);
    const float h = (view.h - gap * static_cast<float>(rows - 1)) / static_cast<float>(rows);
    std::vector<ViewPane> panes;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t col = k % cols, row = k / cols;
        panes.push_back({{view.x + static_cast<float>(col) * (w + gap), view.y + static_cast<float>(row) * (h + gap), w, h}, shown[k]});
    }
    return panes;
}

}  // namespace pl::app
