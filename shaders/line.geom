#version 330 core
// Expands each segment into a screen-space quad u_width_px wide (core profile has no wide
// lines), one pixel wider on each side for the anti-aliased edge the fragment shader fades.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in vec4 v_color[];
out vec4 g_color;
out float g_across;   // -1 .. 1 across the quad

uniform vec2 u_viewport_size;   // pixels
uniform float u_width_px;

void main() {
    vec4 p0 = gl_in[0].gl_Position;
    vec4 p1 = gl_in[1].gl_Position;
    vec4 c0 = v_color[0];
    vec4 c1 = v_color[1];
    // Clip against the plane w = eps so segments passing behind the camera stay finite.
    const float eps = 1e-4;
    if (p0.w < eps && p1.w < eps) return;
    if (p0.w < eps) {
        float t = (eps - p0.w) / (p1.w - p0.w);
        p0 = mix(p0, p1, t);
        c0 = mix(c0, c1, t);
    } else if (p1.w < eps) {
        float t = (eps - p1.w) / (p0.w - p1.w);
        p1 = mix(p1, p0, t);
        c1 = mix(c1, c0, t);
    }
    vec2 half_size = 0.5 * u_viewport_size;
    vec2 s0 = p0.xy / p0.w * half_size;
    vec2 s1 = p1.xy / p1.w * half_size;
    vec2 d = s1 - s0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 offset = vec2(-dir.y, dir.x) * (0.5 * u_width_px + 1.0) / half_size;

    g_color = c0; g_across = -1.0; gl_Position = vec4(p0.xy + offset * p0.w, p0.zw); EmitVertex();
    g_color = c0; g_across = 1.0;  gl_Position = vec4(p0.xy - offset * p0.w, p0.zw); EmitVertex();
    g_color = c1; g_across = -1.0; gl_Position = vec4(p1.xy + offset * p1.w, p1.zw); EmitVertex();
    g_color = c1; g_across = 1.0;  gl_Position = vec4(p1.xy - offset * p1.w, p1.zw); EmitVertex();
    EndPrimitive();
}
