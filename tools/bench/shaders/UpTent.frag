// Tent upsample: a 3x3 tent (weights 1 2 1 / 2 4 2 / 1 2 1, over 16) of the smaller level, added
// (blend ONE, ONE) onto the level twice its size.
#version 430 core

layout(binding = 0) uniform sampler2D s2Source;
layout(location = 0) uniform vec2 v2InvTarget;
layout(location = 1) uniform vec2 v2SourceTexel;

out vec3 v3Colour;

vec3 tap(vec2 v2UV, float x, float y) { return texture(s2Source, v2UV + v2SourceTexel * vec2(x, y)).rgb; }

void main() {
    vec2 v2UV = gl_FragCoord.xy * v2InvTarget;
    vec3 v3Sum = tap(v2UV, 0.0f, 0.0f) * 4.0f;
    v3Sum += (tap(v2UV, -1.0f, 0.0f) + tap(v2UV, 1.0f, 0.0f) + tap(v2UV, 0.0f, -1.0f) + tap(v2UV, 0.0f, 1.0f)) * 2.0f;
    v3Sum += tap(v2UV, -1.0f, -1.0f) + tap(v2UV, 1.0f, -1.0f) + tap(v2UV, -1.0f, 1.0f) + tap(v2UV, 1.0f, 1.0f);
    v3Colour = v3Sum / 16.0f;
}
