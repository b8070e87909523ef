#version 330 core
// Blinn-Phong key light + sky/ground hemisphere ambient + a soft rim so spheres read as round
// against the dark room.
in vec3 v_normal;
in vec3 v_world;
in vec4 v_color;

uniform vec3 u_eye;
uniform vec3 u_light_dir;   // towards the light, world space

out vec4 frag_color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(u_light_dir);
    vec3 v = normalize(u_eye - v_world);
    float diffuse = max(dot(n, l), 0.0);
    float hemi = 0.5 + 0.5 * n.y;
    vec3 ambient = mix(vec3(0.16, 0.15, 0.15), vec3(0.40, 0.43, 0.50), hemi);
    vec3 h = normalize(l + v);
    float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.40;
    float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0) * 0.30;
    vec3 c = v_color.rgb * (ambient + 0.85 * diffuse) + vec3(specular) + rim * v_color.rgb;
    frag_color = vec4(c, v_color.a);
}
