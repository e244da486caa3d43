// Luminance pass (steps 2-5, 17-18): writes each pixel's log luminance, mapped to [0, 1] so that an
// integer (GL_R16) texture can hold it and glGenerateMipmap can average it into the scene key,
// and the pixels bright enough to bloom. The exercises make the white point (step 37) and the
// bloom threshold (step 38) uniforms, and skip the range mapping for a GL_R16F texture (step 40).
#version 430 core

// [step 2] The luminance shader: inputs, the luminance output and main()
layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;

layout(location = 0) out float fYOut;
// [step 17] The bloom output
layout(location = 1) out vec3 v3YBloomOut;
// [/step 17]
// [step 37] The white point Yw, set by the host (it was the constant 0.22 of step 5)
layout(location = 0) uniform float fYwhite;
// [/step 37]
// [step 38] The bloom threshold as a multiple of Yw (it was the constant 2.95 of step 18)
layout(location = 1) uniform float fBloomThreshold;
// [/step 38]
// [step 40] Range mapping on (GL_R16) or off (GL_R16F holds log luminance as it is)
layout(location = 2) uniform bool bRangeMapping;
// [/step 40]

void main() {
    // [step 3] Luminance (CIE Y) of the linear sRGB accumulation colour
    // Get UV coordinates
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;

    // Get colour data
    vec3 v3AccumColour = texture(s2AccumulationTexture, v2UV).rgb;

    // Calculate luminance
    const vec3 v3LuminanceConvert = vec3(0.2126f, 0.7152f, 0.0722f);
    float fY = dot(v3AccumColour, v3LuminanceConvert);
    // [/step 3]

    // [step 4] Calculate log luminance (epsilon keeps log away from 0)
    const float fEpsilon = 0.00000001f;
    float fYoutTemp = log(fY + fEpsilon);
    // [/step 4]

    // [step 5] Map [log(epsilon), log(Yw)] to [0, 1]. Anything brighter than Yw saturates to 1 in
    // GL_R16, so very bright scenes get a key lower than their true log-average (exercise 40)
    // Perform range mapping (optional: only needed with integer textures)
    // [step 40] Only for the integer texture
    if (bRangeMapping) {
        fYoutTemp = (fYoutTemp - log(fEpsilon)) / (log(fYwhite) - log(fEpsilon));
    }
    // [/step 40]

    fYOut = fYoutTemp;
    // [/step 5]

    // [step 18] Output bloom values: the threshold is a multiple of the white point, so it acts
    // on approximate post-tone-map brightness before the tone map has run
    // [step 38] The threshold is the uniform multiple of Yw
    v3YBloomOut = (fY >= fYwhite * fBloomThreshold)? v3AccumColour : vec3(0.0f);
    // [/step 38]
    // [/step 18]
}
// [/step 2]
