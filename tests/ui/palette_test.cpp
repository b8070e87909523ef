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

TEST(Palette, GoldenAngleHuesEqualTheFmodFormulaForEveryIndexUpToTenMillion) {
    for (int index = 10; index < 10'000'000; index += (index < 100'000 ? 1 : 997)) {
        const double by_fmod = std::fmod(0.618033988749895 * index, 1.0) * 6.0;
        ASSERT_EQ(golden_hue_sector(index), by_fmod) << "index " << index;
        ASSERT_EQ(series_color(index), light_color_of_hue(by_fmod)) << "index " << index;
    }
}

TEST(Palette, HueSectorsGoRoundTheWheel) {
    // Red at 0, yellow at 1, green at 2, cyan at 3, blue at 4, magenta at 5 (lightened).
    const float hi = 0.95f, lo = static_cast<float>(0.95 * 0.45);
    EXPECT_EQ(light_color_of_hue(0.0), (Rgba{hi, lo, lo, 1.0f}));
    EXPECT_EQ(light_color_of_hue(2.0), (Rgba{lo, hi, lo, 1.0f}));
    EXPECT_EQ(light_color_of_hue(4.0), (Rgba{lo, lo, hi, 1.0f}));
    const Rgba yellow = light_color_of_hue(1.0);
    EXPECT_FLOAT_EQ(yellow[0], hi);
    EXPECT_FLOAT_EQ(yellow[1], hi);
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
