// Light cubes: emissive, so they output the light's linear HDR colour unlit, scaled to the radiance
// of a small, very bright lamp (luminance 50 and more). They are the brightest pixels of the scene
// and what bloom spreads.
#version 430 core

layout(location = 0) flat in vec3 v3Colour;

// A lamp is small: its surface is far brighter than the light it casts on the room suggests.
layout(location = 1) uniform float fRadiancePerIntensity;

layout(location = 0) out vec4 v4Colour;

void main() {
    v4Colour = vec4(v3Colour * fRadiancePerIntensity, 1.0f);
}
