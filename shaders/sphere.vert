#version 330 core
// Instanced sphere: one unit-sphere mesh, per-instance centre, radius and colour.
layout(location = 0) in vec3 a_unit;             // unit-sphere vertex (= its normal)
layout(location = 1) in vec4 a_center_radius;    // per instance: centre (m), radius (m)
layout(location = 2) in vec4 a_color;            // per instance

uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec3 u_forward;               // camera view direction
uniform float u_min_radius_per_depth; // smallest drawn radius per metre of depth (a few pixels)

out vec3 v_normal;
out vec3 v_world;
out vec4 v_color;

void main() {
    // Tiny particles are drawn a few pixels wide so they never vanish from the view.
    float depth = max(dot(a_center_radius.xyz - u_eye, u_forward), 0.0);
    float radius = max(a_center_radius.w, u_min_radius_per_depth * depth);
    vec3 world = a_center_radius.xyz + radius * a_unit;
    v_normal = a_unit;
    v_world = world;
    v_color = a_color;
    gl_Position = u_view_proj * vec4(world, 1.0);
}
