// The CPU point splat (app/point_splat.hpp) draws what the point sprite shaders draw: a disc of
// the projected diameter at the projected centre, the nearest particle in front, nothing the GL
// would clip. (tests/gui/point_splat.sh compares it with llvmpipe's own points, pixel by pixel.)
#include "app/point_splat.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pl::app {
namespace {

constexpr int width = 200, height = 100;

struct Camera {
    glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    glm::mat4 proj = glm::perspective(glm::radians(45.0f), 2.0f, 0.1f, 100.0f);
};

SphereInstance ball(glm::vec3 c, float r, glm::vec4 color) { return {glm::vec4(c, r), color}; }

// The radius that projects to `diameter_px` at depth `distance` (the shader's own formula).
float radius_for(float diameter_px, float distance, const Camera& cam) {
    return diameter_px * distance / (cam.proj[1][1] * static_cast<float>(height));
}

long covered(const SplatImage& image) {
    long n = 0;
    for (std::uint32_t px : image.rgba) n += (px >> 24) != 0;
    return n;
}

TEST(PointSplat, ADiscOfTheProjectedDiameterAtTheProjectedCentre) {
    const Camera cam;
    SplatImage image;
    const float diameter = 30.0f;
    splat_points({ball({0, 0, 0}, radius_for(diameter, 10.0f, cam), {1, 0, 0, 1})}, cam.view, cam.proj, width, height,
                 image);
    const double area = std::numbers::pi * diameter * diameter / 4.0;
    EXPECT_NEAR(static_cast<double>(covered(image)), area, std::numbers::pi * diameter);  // within a perimeter
    // Centred: the image's middle pixels are covered, and the disc is symmetric left to right.
    EXPECT_NE(image.at(width / 2, height / 2) >> 24, 0u);
    EXPECT_EQ(image.at(width / 2 - 14, height / 2) >> 24, image.at(width / 2 + 13, height / 2) >> 24);
    EXPECT_EQ(image.at(width / 2 - 17, height / 2) >> 24, 0u);
    // Shaded as a sphere lit from the upper right: brighter there than at the lower left.
    const auto red = [&](int x, int y) { return image.at(x, y) & 0xffu; };
    EXPECT_GT(red(width / 2 + 6, height / 2 + 6), red(width / 2 - 6, height / 2 - 6));
    EXPECT_EQ((image.at(width / 2, height / 2) >> 8) & 0xffu, 0u);  // no green in a red ball
    // The depth is the centre's window depth.
    const glm::vec4 clip = cam.proj * cam.view * glm::vec4(0, 0, 0, 1);
    EXPECT_FLOAT_EQ(image.depth[static_cast<std::size_t>(height / 2) * width + width / 2], clip.z / clip.w * 0.5f + 0.5f);
}

TEST(PointSplat, TheNearerParticleCoversTheFartherInEitherOrder) {
    const Camera cam;
    const SphereInstance near = ball({0, 0, 2}, 0.3f, {0, 1, 0, 1}), far = ball({0, 0, -2}, 0.3f, {0, 0, 1, 1});
    for (const auto& order : {std::vector{near, far}, std::vector{far, near}}) {
        SplatImage image;
        splat_points(order, cam.view, cam.proj, width, height, image);
        const std::uint32_t centre = image.at(width / 2, height / 2);
        EXPECT_GT((centre >> 8) & 0xffu, 0u);   // green: the near one
        EXPECT_EQ((centre >> 16) & 0xffu, 0u);  // no blue
    }
}

TEST(PointSplat, TinyParticlesStayVisibleAndHugeOnesAreCapped) {
    const Camera cam;
    SplatImage image;
    splat_points({ball({0, 0, 0}, 1e-6f, {1, 1, 1, 1})}, cam.view, cam.proj, width, height, image);
    EXPECT_GE(covered(image), 2);  // at least the 2 px diameter
    EXPECT_LE(covered(image), 4);
    splat_points({ball({0, 0, 0}, 50.0f, {1, 1, 1, 1})}, cam.view, cam.proj, width, height, image);
    EXPECT_LE(covered(image), static_cast<long>(std::numbers::pi * 32 * 32 + std::numbers::pi * 64));  // 64 px at most
}

TEST(PointSplat, NothingTheGlWouldClipAndNothingOutsideTheImage) {
    const Camera cam;
    SplatImage image;
    splat_points({ball({0, 0, 20}, 0.3f, {1, 1, 1, 1}),     // behind the eye
                  ball({0, 0, -200}, 50.0f, {1, 1, 1, 1}),  // beyond the far plane
                  ball({0, 0, 9.95f}, 0.3f, {1, 1, 1, 1})},  // nearer than the near plane
                 cam.view, cam.proj, width, height, image);
    EXPECT_EQ(covered(image), 0);
    // Centres on the edges and corners: the discs are cut at the border (ASan checks the writes).
    const float x_edge = 10.0f * std::tan(glm::radians(22.5f)) * 2.0f, y_edge = 10.0f * std::tan(glm::radians(22.5f));
    splat_points({ball({x_edge, 0, 0}, 0.5f, {1, 1, 1, 1}), ball({-x_edge, -y_edge, 0}, 0.5f, {1, 1, 1, 1}),
                  ball({x_edge, y_edge, 0}, 0.5f, {1, 1, 1, 1})},
                 cam.view, cam.proj, width, height, image);
    EXPECT_GT(covered(image), 0);
    splat_points({}, cam.view, cam.proj, 0, 0, image);  // an empty pane
    EXPECT_EQ(covered(image), 0);
}

}  // namespace
}  // namespace pl::app
