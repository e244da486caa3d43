// LearnOpenGL-style bloom, one ping-pong pass: a 9-tap Gaussian along one axis (the centre and four
// texels each side, five distinct weights summing to 1), one texel apart, no bilinear tricks.
#version 430 core

layout(binding = 0) uniform sampler2D s2Source;
layout(location = 0) uniform vec2 v2InvTarget;
layout(location = 1) uniform vec2 v2Step; // one source texel along the pass's axis

out vec4 v4Colour;

const float fWeights[5] = float[](0.2270270f, 0.1945946f, 0.1216216f, 0.0540540f, 0.0162162f);

void main() {
    vec2 v2UV = gl_FragCoord.xy * v2InvTarget;
    vec3 v3Sum = texture(s2Source, v2UV).rgb * fWeights[0];
    for (int i = 1; i < 5; ++i) {
        v3Sum += texture(s2Source, v2UV + v2Step * float(i)).rgb * fWeights[i];
        v3Sum += texture(s2Source, v2UV - v2Step * float(i)).rgb * fWeights[i];
    }
    v4Colour = vec4(v3Sum, 1.0f);
}
