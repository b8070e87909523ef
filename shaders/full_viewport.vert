#version 330 core
// Full-viewport triangle from gl_VertexID (no vertex buffer), at the far end of the depth range:
// the background's (which shades by v_height) and the splat image's (which writes its own depth).
out float v_height;   // 0 at the bottom, 1 at the top

void main() {
    vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
    v_height = 0.5 * (p.y + 1.0);
    gl_Position = vec4(p, 0.999, 1.0);
}
