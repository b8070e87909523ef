#version 330 core
in vec2 v_corner;
in float v_strength;
out vec4 frag_color;

void main() {
    float r2 = dot(v_corner, v_corner);
    if (r2 > 1.0) discard;
    frag_color = vec4(0.0, 0.0, 0.0, v_strength * (1.0 - smoothstep(0.2, 1.0, r2)));
}
