// LearnOpenGL-style bloom, final pass: HDR colour plus bloom, exposure tone map, gamma 2.2.
#version 430 core

layout(binding = 0) uniform sampler2D s2Hdr;
layout(binding = 1) uniform sampler2D s2Bloom;
layout(location = 0) uniform vec2 v2InvTarget;

out vec4 v4Colour;

const float fExposure = 1.0f;

void main() {
    vec2 v2UV = gl_FragCoord.xy * v2InvTarget;
    vec3 v3Hdr = texture(s2Hdr, v2UV).rgb + texture(s2Bloom, v2UV).rgb;
    vec3 v3Mapped = vec3(1.0f) - exp(-v3Hdr * fExposure);
    v4Colour = vec4(pow(v3Mapped, vec3(1.0f / 2.2f)), 1.0f);
}
