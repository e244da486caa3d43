// Scene surfaces: parallax occlusion mapping (a layered search through the depth map with linear
// interpolation between the last two layers), tangent-space normal mapping, per-fragment
// Blinn-Phong lighting from the HDR point and spot lights, and emission (glTF emissive factor x
// KHR_materials_emissive_strength: the light cubes and any bright source of a --scene file). Writes
// linear HDR colour (values far above 1 near the lights) into the GL_RGBA16F accumulation texture.
#version 430 core

const int kMaxLights = 8; // must match Scene's kMaxLights on the host

layout(std140, binding = 0) uniform Camera {
    mat4 m4View;
    mat4 m4Projection;
    vec4 v4CameraPos;
};

layout(std140, binding = 1) uniform Lights {
    vec4 v4LightPos[kMaxLights];    // xyz: world position
    vec4 v4LightColour[kMaxLights]; // rgb: linear HDR intensity (candela for a glTF light)
    vec4 v4LightSpot[kMaxLights];   // xyz: spot direction, w: cos(outer cone angle); -2 = point light
    vec4 v4LightCone[kMaxLights];   // x: cos(inner cone angle), y: 1 / range (0 = unlimited)
    int iLightCount;
};

layout(binding = 0) uniform sampler2D s2DiffuseMap;  // sRGB texture: reads back linear
layout(binding = 1) uniform sampler2D s2NormalMap;   // tangent space, +y along +v
layout(binding = 2) uniform sampler2D s2DepthMap;    // 0 = top of the surface, 1 = deepest
layout(binding = 3) uniform sampler2D s2EmissiveMap; // sRGB texture

layout(location = 0) uniform float fParallaxScale; // UV units the deepest point lies below the top
layout(location = 1) uniform float fShininess;
layout(location = 2) uniform float fSpecular;
layout(location = 3) uniform vec4 v4BaseColour;    // multiplies the diffuse map (glTF baseColorFactor)
layout(location = 4) uniform vec3 v3Emissive;      // multiplies the emissive map, linear HDR
layout(location = 5) uniform int iAlphaMode;       // 0 opaque, 1 mask, 2 blend
layout(location = 6) uniform float fAlphaCutoff;   // mask: fragments below it are discarded
layout(location = 7) uniform float fNormalScale;   // scales the normal map's x and y
// At most this many parallax layers (grazing views; 100 unless a window on a software renderer
// lowers it while the camera moves, see Scene::setRenderOnChange).
layout(location = 8) uniform float fMaxParallaxLayers;

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
    float fMaxLayers = max(fMaxParallaxLayers, fMinLayers);
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
    // A double-sided surface seen from behind is lit as the side the camera sees (single-sided
    // ones are culled before they get here).
    if (!gl_FrontFacing) {
        v3N = -v3N;
        v3T = -v3T;
        v3B = -v3B;
    }
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
    // tools/make_scene), and crate faces span [0, 1].
    if (any(lessThan(v2TexCoord, v4UVBounds.xy)) || any(greaterThan(v2TexCoord, v4UVBounds.zw))) discard;
    float fDepth = v3Parallax.z;

    vec4 v4Albedo = textureGrad(s2DiffuseMap, v2TexCoord, v2Dx, v2Dy) * v4BaseColour;
    if (iAlphaMode == 1 && v4Albedo.a < fAlphaCutoff) discard;
    vec3 v3Albedo = v4Albedo.rgb;
    vec3 v3MapNormal = textureGrad(s2NormalMap, v2TexCoord, v2Dx, v2Dy).xyz * 2.0f - 1.0f;
    v3MapNormal.xy *= fNormalScale;
    vec3 v3Bumped = normalize(m3TBN * v3MapNormal); // the mapped normal, in world space

    // Crevices get less ambient light and are less glossy than the tops.
    vec3 v3Result = kAmbient * (1.0f - 0.6f * fDepth) * v3Albedo;
    float fGloss = fSpecular * (1.0f - 0.8f * fDepth);
    for (int i = 0; i < iLightCount; ++i) {
        vec3 v3ToLight = v4LightPos[i].xyz - v3Position;
        float fDistance2 = dot(v3ToLight, v3ToLight);
        vec3 v3L = v3ToLight * inversesqrt(fDistance2);
        vec3 v3Radiance = v4LightColour[i].rgb / (fDistance2 + kFalloffSoftening);
        if (v4LightCone[i].y > 0.0f) {
            // glTF's range: a smooth window that reaches zero at the range.
            float fRatio = sqrt(fDistance2) * v4LightCone[i].y;
            v3Radiance *= pow(clamp(1.0f - pow(fRatio, 4.0f), 0.0f, 1.0f), 2.0f);
        }
        if (v4LightSpot[i].w > -1.5f) {
            // Spot cone: full inside the inner angle, none outside the outer, smooth between.
            float fCos = dot(-v3L, v4LightSpot[i].xyz);
            float fCone = clamp((fCos - v4LightSpot[i].w) / max(v4LightCone[i].x - v4LightSpot[i].w, 1e-4f), 0.0f, 1.0f);
            v3Radiance *= fCone * fCone;
        }
        // Lights behind the face itself do not reach it, whatever the mapped normal says.
        float fFacing = smoothstep(-0.05f, 0.15f, dot(v3N, v3L));

        float fDiffuse = max(dot(v3Bumped, v3L), 0.0f);
        vec3 v3H = normalize(v3L + v3ViewDir);
        float fSpec = pow(max(dot(v3Bumped, v3H), 0.0f), fShininess) * fGloss;
        v3Result += fFacing * v3Radiance * (fDiffuse * v3Albedo + fSpec);
    }
    v3Result += v3Emissive * textureGrad(s2EmissiveMap, v2TexCoord, v2Dx, v2Dy).rgb;
    v4Colour = vec4(v3Result, iAlphaMode == 2 ? v4Albedo.a : 1.0f);
}
