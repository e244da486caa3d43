// The final pass with the key math done once per vertex instead of once per pixel: the key Ya and
// the middle grey dg are the same for every pixel, so the vertex shader reads the 1x1 level, undoes
// the range mapping and hands dg / Ya to the fragment shader as a flat value.
#version 430 core

layout(location = 0) in vec2 v2VertexPos;
layout(binding = 16) uniform sampler2D s2LuminanceKeyTexture;

layout(location = 0) flat out float fKeyScale;

void main() {
    const float fYwhite = 0.22f;
    const float fEpsilon = 0.00000001f;
    float fYa = textureLod(s2LuminanceKeyTexture, vec2(0.5f), 1000.0f).r;
    fYa = exp(fYa * (log(fYwhite) - log(fEpsilon)) + log(fEpsilon));
    float fDg = 1.03f - 2.0f / (2.0f + log2(fYa + 1.0f) * 0.30102999566f);
    fKeyScale = fDg / fYa;
    gl_Position = vec4(v2VertexPos, 0.0f, 1.0f);
}
