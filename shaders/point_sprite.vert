#version 330 core
// Many particles: one screen-aligned point per particle, sized to the sphere's projected diameter.
layout(location = 1) in vec4 a_center_radius;
layout(location = 2) in vec4 a_color;

uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_viewport_height;   // pixels
uniform vec2 u_size_range;         // smallest and largest diameter drawn, pixels (app/point_splat.hpp)

out vec4 v_color;

void main() {
    vec4 eye = u_view * vec4(a_center_radius.xyz, 1.0);
    gl_Position = u_proj * eye;
    // Projected diameter: 2 r * (f / z) * (H / 2), with f = proj[1][1] = 1 / tan(fov / 2).
    float diameter = a_center_radius.w * u_proj[1][1] * u_viewport_height / max(-eye.z, 1e-4);
    gl_PointSize = clamp(diameter, u_size_range.x, u_size_range.y);
    v_color = a_color;
}
