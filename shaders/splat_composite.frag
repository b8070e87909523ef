#version 330 core
// Draws the particles splatted on the CPU (app/point_splat.hpp): each pixel's colour and window
// depth from the two images, so the depth test and blending treat it as the point sprite's own.
uniform sampler2D u_color;
uniform sampler2D u_depth;
uniform ivec2 u_origin;   // the pane's lower-left corner in window pixels

out vec4 frag_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - u_origin;
    vec4 c = texelFetch(u_color, p, 0);
    if (c.a == 0.0) discard;
    frag_color = c;
    gl_FragDepth = texelFetch(u_depth, p, 0).r;
}
