// 13-tap downsample (the "next generation post-processing" bloom): five overlapping 2x2 boxes of
// bilinear taps, the centre box weighted 0.5 and the four corner boxes 0.125 each, which keeps
// the halving free of aliasing flicker. Reads the level above (twice this target's size).
#version 430 core

layout(binding = 0) uniform sampler2D s2Source;
layout(location = 0) uniform vec2 v2InvTarget;
layout(location = 1) uniform vec2 v2SourceTexel; // 1 / source size

out vec3 v3Colour;

vec3 tap(vec2 v2UV, float x, float y) { return texture(s2Source, v2UV + v2SourceTexel * vec2(x, y)).rgb; }

void main() {
    vec2 v2UV = gl_FragCoord.xy * v2InvTarget;
    vec3 v3Outer = tap(v2UV, -2.0f, 2.0f) + tap(v2UV, 2.0f, 2.0f) + tap(v2UV, -2.0f, -2.0f) + tap(v2UV, 2.0f, -2.0f);
    vec3 v3Edges = tap(v2UV, 0.0f, 2.0f) + tap(v2UV, -2.0f, 0.0f) + tap(v2UV, 2.0f, 0.0f) + tap(v2UV, 0.0f, -2.0f);
    vec3 v3Inner = tap(v2UV, -1.0f, 1.0f) + tap(v2UV, 1.0f, 1.0f) + tap(v2UV, -1.0f, -1.0f) + tap(v2UV, 1.0f, -1.0f);
    v3Colour = tap(v2UV, 0.0f, 0.0f) * 0.125f + v3Outer * 0.03125f + v3Edges * 0.0625f + v3Inner * 0.125f;
}
