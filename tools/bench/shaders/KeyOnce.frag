// The tutorial's final pass (bloom, then the tone map) with dg / Ya from KeyOnce.vert: per pixel
// only the colour, the bloom and the tone curve remain.
#version 430 core

layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;
layout(binding = 17) uniform sampler2D s2BloomTexture;

layout(location = 0) flat in float fKeyScale;
layout(location = 0) out vec3 v3ColourOut;

void main() {
    const float fYwhite = 0.22f;
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;
    vec3 v3Colour = texture(s2AccumulationTexture, v2UV).rgb + texture(s2BloomTexture, v2UV, 1024.0f).rgb * 0.98f;
    float fY = dot(v3Colour, vec3(0.2126f, 0.7152f, 0.0722f));
    float fYr = fKeyScale * fY;
    float fYNew = (fYr * (1.0f + fYr / (fYwhite * fYwhite))) / (1.0f + fYr);
    v3ColourOut = fY > 0.0f ? v3Colour * (fYNew / fY) : vec3(0.0f);
}
