// Point sprites drawn on the CPU, for a CPU rasteriser. Mesa's llvmpipe spends about 0.5 us of
// its single vertex-and-setup thread on every GL point (vertex fetch, shading, clipping, binning
// into tiles), whatever the point's size: 1e5 particles cost it 50 ms a frame, half a core at
// 10 frames a second, taken from the physics. Splatting the same discs into a colour and depth
// image here costs a few milliseconds; the GL side then draws that image once (renderer_splat).
//
// Each particle is drawn as the point sprite shaders (shaders/point_sprite.*) draw it: a square
// of the projected diameter (clamped to 2..64 px) centred on the projected centre, the pixels
// whose centres lie in its inscribed disc, shaded as a sphere seen head-on and given the centre's
// window depth. A pixel keeps the nearest disc (the GL depth test, GL_LEQUAL: of equal depths the
// later particle wins). The image has GL's orientation: row 0 at the bottom.
#pragma once

#include "app/renderer_instances.hpp"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace pl::app {

// Sizes of a drawn point, the same numbers the point sprite shader uses.
constexpr float min_point_diameter_px = 2.0f;
constexpr float max_point_diameter_px = 64.0f;

struct SplatImage {
    int width = 0, height = 0;
    std::vector<std::uint32_t> rgba;  // RGBA8 in memory order R, G, B, A; alpha 0 where no particle
    std::vector<float> depth;         // window depth in [0, 1]; above 1 where no particle

    void clear(int w, int h);
    std::uint32_t at(int x, int y) const { return rgba[static_cast<std::size_t>(y) * width + x]; }
};

// Clears `image` to `width` x `height` and draws every instance into it.
void splat_points(const std::vector<SphereInstance>& instances, const glm::mat4& view, const glm::mat4& proj,
                  int width, int height, SplatImage& image);

}  // namespace pl::app
