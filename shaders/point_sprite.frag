#version 330 core
// Shades the point as a sphere seen head-on (normal rebuilt from the point coordinate).
in vec4 v_color;
out vec4 frag_color;

void main() {
    vec2 d = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(d, d);
    if (r2 > 1.0) discard;
    vec3 n = vec3(d.x, -d.y, sqrt(1.0 - r2));
    float diffuse = max(dot(n, normalize(vec3(0.35, 0.65, 0.65))), 0.0);
    vec3 c = v_color.rgb * (0.35 + 0.75 * diffuse);
    frag_color = vec4(c, v_color.a);
}
