// The series colours: the plots and the 3D view must agree on a particle's colour, and the 3D
// view computes it for every particle of every frame, so the golden-angle hue is taken as a
// fractional part by floor. That must be the same value std::fmod gives, for every index a
// scene can hold.
#include "ui/palette.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace pl::ui {
namespace {

// The hue sector the palette uses, as it was first written (std::fmod).
double hue_by_fmod(int index) { return std::fmod(0.618033988749895 * index, 1.0) * 6.0; }

// The same HSV-to-RGB conversion with the fmod hue, for comparison.
Rgba color_by_fmod(int index) {
    const double hue = hue_by_fmod(index);
    const double s = 0.55, v = 0.95;
    const double f = hue - std::floor(hue);
    const auto p = static_cast<float>(v * (1 - s)), q = static_cast<float>(v * (1 - s * f)),
               t = static_cast<float>(v * (1 - s * (1 - f))), w = static_cast<float>(v);
    switch (static_cast<int>(hue) % 6) {
        case 0: return {w, t, p, 1.0f};
        case 1: return {q, w, p, 1.0f};
        case 2: return {p, w, t, 1.0f};
        case 3: return {p, q, w, 1.0f};
        case 4: return {t, p, w, 1.0f};
        default: return {w, p, q, 1.0f};
    }
}

TEST(Palette, GoldenAngleHuesEqualTheFmodFormulaForEveryIndexUpToTenMillion) {
    for (int index = 10; index < 10'000'000; index += (index < 100'000 ? 1 : 997))
        ASSERT_EQ(series_color(index), color_by_fmod(index)) << "index " << index;
}

TEST(Palette, NeighbouringSeriesHaveDistinctColours) {
    for (int index = 0; index < 1000; ++index) EXPECT_NE(series_color(index), series_color(index + 1)) << index;
    std::set<Rgba> first_hundred;
    for (int index = 0; index < 100; ++index) first_hundred.insert(series_color(index));
    EXPECT_EQ(first_hundred.size(), 100u);
}

TEST(Palette, VariantsDecideTheColourWhenThereAreSeveral) {
    const Rgb one_variant = series_color(std::size_t{1}, std::size_t{0}, std::size_t{7});
    const Rgba seventh = series_color(7);
    EXPECT_EQ(one_variant.r, seventh[0]);
    const Rgb second_of_three = series_color(std::size_t{3}, std::size_t{1}, std::size_t{7});
    const Rgba second = series_color(1);
    EXPECT_EQ(second_of_three.g, second[1]);
}

}  // namespace
}  // namespace pl::ui
