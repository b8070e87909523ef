// Series colours shared by the plots and the 3D view, so a particle or variant has the same
// colour everywhere. Plain floats (no ImGui, no GL): both the ui and the renderer include it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace pl::ui {

using Rgba = std::array<float, 4>;

struct Rgb {
    float r, g, b;
};

// The hue of series `index` beyond the first ten, as a sector 0..6 of the colour wheel: the
// golden angle times the index, modulo a turn. The fractional part by floor, not std::fmod: the
// same exact value (x - floor(x) is exact for x >= 0) at a fraction of fmod's cost, which the 3D
// view pays once per particle per frame.
inline double golden_hue_sector(int index) {
    const double turns = 0.618033988749895 * index;
    return (turns - std::floor(turns)) * 6.0;
}

// HSV to RGB at saturation 0.55, value 0.95 (light enough on a dark background).
inline Rgba light_color_of_hue(double sector) {
    const double s = 0.55, v = 0.95;
    const double f = sector - std::floor(sector);
    const auto p = static_cast<float>(v * (1 - s)), q = static_cast<float>(v * (1 - s * f)),
               t = static_cast<float>(v * (1 - s * (1 - f))), w = static_cast<float>(v);
    switch (static_cast<int>(sector) % 6) {
        case 0: return {w, t, p, 1.0f};
        case 1: return {q, w, p, 1.0f};
        case 2: return {p, w, t, 1.0f};
        case 3: return {p, q, w, 1.0f};
        case 4: return {t, p, w, 1.0f};
        default: return {w, p, q, 1.0f};
    }
}

// Distinct on a dark background: the Tableau 10 hues, lightened a little. Beyond ten series the
// hue advances by the golden angle, which keeps neighbours apart however many there are.
inline Rgba series_color(int index) {
    static constexpr std::array<Rgba, 10> base{{
        {0.31f, 0.61f, 0.91f, 1.0f},  // blue
        {1.00f, 0.58f, 0.20f, 1.0f},  // orange
        {0.35f, 0.78f, 0.35f, 1.0f},  // green
        {0.95f, 0.33f, 0.33f, 1.0f},  // red
        {0.72f, 0.55f, 0.90f, 1.0f},  // purple
        {0.80f, 0.60f, 0.50f, 1.0f},  // brown
        {0.97f, 0.55f, 0.85f, 1.0f},  // pink
        {0.75f, 0.75f, 0.75f, 1.0f},  // grey
        {0.85f, 0.85f, 0.30f, 1.0f},  // olive
        {0.30f, 0.85f, 0.90f, 1.0f},  // cyan
    }};
    if (index < 0) index = 0;
    if (index < static_cast<int>(base.size())) return base[static_cast<std::size_t>(index)];
    return light_color_of_hue(golden_hue_sector(index));
}

// Which palette entry a particle of a variant uses: with several variants the variant decides
// (the 3D view overlays variants, the plots draw one line per variant); otherwise each particle
// has its own colour.
inline int color_index(std::size_t variant, std::size_t particle, std::size_t variant_count) {
    return static_cast<int>(variant_count > 1 ? variant : particle);
}

// The colour of particle `particle` of variant `variant` (the renderer's entry point).
inline Rgb series_color(std::size_t variant_count, std::size_t variant, std::size_t particle) {
    const Rgba c = series_color(color_index(variant, particle, variant_count));
    return {c[0], c[1], c[2]};
}

}  // namespace pl::ui
