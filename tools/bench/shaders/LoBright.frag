// LearnOpenGL-style bloom, bright pass: the HDR colour where its luminance reaches the threshold,
// into a separate RGBA16F target (full or half resolution). Written from the published
// description; the threshold is the tutorial's 2.95 x Yw so both chains bloom the same pixels.
#version 430 core

layout(binding = 0) uniform sampler2D s2Hdr;
layout(location = 0) uniform vec2 v2InvTarget;

out vec4 v4Bright;

void main() {
    vec3 v3Colour = texture(s2Hdr, gl_FragCoord.xy * v2InvTarget).rgb;
    float fY = dot(v3Colour, vec3(0.2126f, 0.7152f, 0.0722f));
    v4Bright = vec4(fY >= 0.22f * 2.95f ? v3Colour : vec3(0.0f), 1.0f);
}
