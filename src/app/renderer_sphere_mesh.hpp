// The unit sphere every particle is drawn from (instanced).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace pl::app {

struct UnitSphereMesh {
    std::vector<glm::vec3> vertices;  // on the unit sphere, so each is also its normal
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// Icosahedron subdivided `subdivisions` times (3 gives 1280 triangles: smooth at any size a
// particle takes on screen).
UnitSphereMesh make_unit_icosphere(int subdivisions);

}  // namespace pl::app
