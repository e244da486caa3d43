// Light cubes: emissive, so they output the light's linear HDR colour unlit (components up to 15).
// These are the brightest pixels of the scene and what bloom spreads.
#version 430 core

layout(location = 0) flat in vec3 v3Colour;

layout(location = 0) out vec4 v4Colour;

void main() {
    v4Colour = vec4(v3Colour, 1.0f);
}
