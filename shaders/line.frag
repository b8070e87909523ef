#version 330 core
in vec4 g_color;
in float g_across;

uniform float u_width_px;

out vec4 frag_color;

void main() {
    float half_total = 0.5 * u_width_px + 1.0;
    float coverage = clamp(half_total * (1.0 - abs(g_across)), 0.0, 1.0);
    frag_color = vec4(g_color.rgb, g_color.a * coverage);
}
