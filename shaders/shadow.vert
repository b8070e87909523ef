#version 330 core
// A soft blob under each sphere on the floor: cheap depth cue for where a particle is.
layout(location = 0) in vec2 a_corner;           // -1 .. 1
layout(location = 1) in vec4 a_center_radius;    // per instance

uniform mat4 u_view_proj;
uniform float u_floor_y;
uniform vec3 u_eye;
uniform vec3 u_forward;
uniform float u_min_radius_per_depth;   // as in sphere.vert: the shadow matches the drawn sphere

out vec2 v_corner;
out float v_strength;

void main() {
    float depth = max(dot(a_center_radius.xyz - u_eye, u_forward), 0.0);
    float r = max(a_center_radius.w, u_min_radius_per_depth * depth);
    float height = max(a_center_radius.y - r - u_floor_y, 0.0);
    // The blob widens and fades as the sphere rises.
    float spread = 1.1 * r + 0.08 * height;
    v_strength = 0.55 / (1.0 + 0.6 * height);
    v_corner = a_corner;
    vec3 world = vec3(a_center_radius.x + a_corner.x * spread, u_floor_y, a_center_radius.z + a_corner.y * spread);
    gl_Position = u_view_proj * vec4(world, 1.0);
}
