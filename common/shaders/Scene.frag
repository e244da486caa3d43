// Scene surfaces: parallax occlusion mapping (a layered search through the depth map with linear
// interpolation between the last two layers), tangent-space normal mapping and per-fragment
// Blinn-Phong lighting from the HDR point lights. Writes linear HDR colour (values far above 1 near
// the lights) into the GL_RGBA16F accumulation texture.
#version 430 core

const int kMaxLights = 8; // must match Scene's kMaxLights on the host

layout(std140, binding = 0) uniform Camera {
    mat4 m4View;
    mat4 m4Projection;
    vec4 v4CameraPos;
};

layout(std140, binding = 1) uniform Lights {
    vec4 v4LightPos[kMaxLights];    // xyz: world position
    vec4 v4LightColour[kMaxLights]; // rgb: linear HDR intensity
    int iLightCount;
};

layout(binding = 0) uniform sampler2D s2DiffuseMap; // sRGB texture: reads back linear
layout(binding = 1) uniform sampler2D s2NormalMap;  // tangent space, +y along +v
layout(binding = 2) uniform sampler2D s2DepthMap;   // 0 = top of the surface, 1 = deepest

layout(location = 0) uniform float fParallaxScale; // UV units the deepest point lies below the top
layout(location = 1) uniform float fShininess;
layout(location = 2) uniform float fSpecular;
// Light the surface gives off itself (a window's daylight), times its albedo so that the texture's
// dark joints read as the frame between panes. Black for ordinary surfaces.
layout(location = 3) uniform vec3 v3Emission;

layout(location = 0) in vec3 v3Position;
layout(location = 1) in vec3 v3Normal;
layout(location = 2) in vec3 v3Tangent;
layout(location = 3) in vec3 v3Bitangent;
layout(location = 4) in vec2 v2UV;
layout(location = 5) flat in vec4 v4UVBounds;

layout(location = 0) out vec4 v4Colour;

// Dim: the room is lit by its few bright sources, and the corners they do not reach stay near black.
const float kAmbient = 0.002f;
// Inverse-square falloff, softened so it stays finite very close to a light.
const float kFalloffSoftening = 0.05f;

// Returns the displaced texture coordinate and, in .z, the depth found there.
// v3View points from the fragment to the eye, in tangent space. The loop has non-uniform control
// flow, where implicit derivatives are undefined, so every sample uses the derivatives of the
// undisplaced coordinate, v2Dx and v2Dy.
vec3 parallaxOcclusionMapping(vec2 v2TexCoord, vec3 v3View, vec2 v2Dx, vec2 v2Dy) {
    const float fMinLayers = 10.0f;
    const float fMaxLayers = 100.0f;
    // Looking straight down needs few layers; grazing views need many.
    float fNumLayers = mix(fMaxLayers, fMinLayers, abs(v3View.z));
    float fLayerDepth = 1.0f / fNumLayers;
    // The shift at full depth. z is kept away from 0 so grazing views do not shift without bound.
    vec2 v2Shift = v3View.xy / max(v3View.z, 0.08f) * fParallaxScale;
    vec2 v2DeltaTexCoord = v2Shift / fNumLayers;

    vec2 v2Current = v2TexCoord;
    float fCurrentDepth = textureGrad(s2DepthMap, v2Current, v2Dx, v2Dy).r;
    float fCurrentLayer = 0.0f;
    // The depth map is at most 1, so the search ends within fNumLayers + 1 steps; the counter is
    // only a guard.
    for (int i = 0; i < 101 && fCurrentLayer < fCurrentDepth; ++i) {
        v2Current -= v2DeltaTexCoord;
        fCurrentDepth = textureGrad(s2DepthMap, v2Current, v2Dx, v2Dy).r;
        fCurrentLayer += fLayerDepth;
    }

    // Interpolate between the layer before the crossing and the layer after it.
    vec2 v2Previous = v2Current + v2DeltaTexCoord;
    float fAfter = fCurrentDepth - fCurrentLayer;
    float fBefore = textureGrad(s2DepthMap, v2Previous, v2Dx, v2Dy).r - fCurrentLayer + fLayerDepth;
    float fWeight = fAfter / (fAfter - fBefore);
    if (!(fWeight >= 0.0f && fWeight <= 1.0f)) fWeight = 0.0f; // first sample already inside: no shift
    vec2 v2Result = mix(v2Current, v2Previous, fWeight);
    return vec3(v2Result, mix(fCurrentLayer, fCurrentLayer - fLayerDepth, fWeight));
}

void main() {
    // Texture-coordinate derivatives, taken here in uniform control flow (before any loop or
    // discard) and used for every sample: the displaced coordinate jumps at each step in the
    // depth map, and its own derivatives would pick tiny mip levels there and draw seams.
    vec2 v2Dx = dFdx(v2UV);
    vec2 v2Dy = dFdy(v2UV);

    vec3 v3N = normalize(v3Normal);
    vec3 v3T = normalize(v3Tangent);
    vec3 v3B = normalize(v3Bitangent);
    mat3 m3TBN = mat3(v3T, v3B, v3N); // tangent space -> world space

    vec3 v3ToEye = v4CameraPos.xyz - v3Position;
    vec3 v3ViewDir = normalize(v3ToEye);
    // The frame is orthonormal, so its transpose takes world vectors into tangent space.
    vec3 v3ViewTangent = normalize(transpose(m3TBN) * v3ToEye);

    vec3 v3Parallax = parallaxOcclusionMapping(v2UV, v3ViewTangent, v2Dx, v2Dy);
    vec2 v2TexCoord = v3Parallax.xy;
    // Trim fragments whose displaced coordinate leaves this face's UV rectangle, so edges show
    // depth instead of the texture wrapping around. The bounds are per face: room faces tile the
    // texture across the whole face, which reaches a little past the room's corners (see
    // scene.cpp), and crate faces span [0, 1].
    if (any(lessThan(v2TexCoord, v4UVBounds.xy)) || any(greaterThan(v2TexCoord, v4UVBounds.zw))) discard;
    float fDepth = v3Parallax.z;

    vec3 v3Albedo = textureGrad(s2DiffuseMap, v2TexCoord, v2Dx, v2Dy).rgb;
    vec3 v3MapNormal = textureGrad(s2NormalMap, v2TexCoord, v2Dx, v2Dy).xyz * 2.0f - 1.0f;
    vec3 v3Bumped = normalize(m3TBN * v3MapNormal); // the mapped normal, in world space

    // Crevices get less ambient light and are less glossy than the tops.
    vec3 v3Result = kAmbient * (1.0f - 0.6f * fDepth) * v3Albedo + v3Emission * v3Albedo;
    float fGloss = fSpecular * (1.0f - 0.8f * fDepth);
    for (int i = 0; i < iLightCount; ++i) {
        vec3 v3ToLight = v4LightPos[i].xyz - v3Position;
        float fDistance2 = dot(v3ToLight, v3ToLight);
        vec3 v3L = v3ToLight * inversesqrt(fDistance2);
        vec3 v3Radiance = v4LightColour[i].rgb / (fDistance2 + kFalloffSoftening);
        // Lights behind the face itself do not reach it, whatever the mapped normal says.
        float fFacing = smoothstep(-0.05f, 0.15f, dot(v3N, v3L));

        float fDiffuse = max(dot(v3Bumped, v3L), 0.0f);
        vec3 v3H = normalize(v3L + v3ViewDir);
        float fSpec = pow(max(dot(v3Bumped, v3H), 0.0f), fShininess) * fGloss;
        v3Result += fFacing * v3Radiance * (fDiffuse * v3Albedo + fSpec);
    }
    v4Colour = vec4(v3Result, 1.0f);
}
