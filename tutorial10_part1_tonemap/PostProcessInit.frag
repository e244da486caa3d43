// Luminance pass (steps 2-5): writes each pixel's log luminance, mapped to [0, 1] so that an
// integer (GL_R16) texture can hold it and glGenerateMipmap can average it into the scene key.
#version 430 core

// [step 2] The luminance shader: inputs, the luminance output and main()
layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;

layout(location = 0) out float fYOut;

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
    const float fYwhite = 0.22f;
    // Perform range mapping (optional: only needed with integer textures)
    fYoutTemp = (fYoutTemp - log(fEpsilon)) / (log(fYwhite) - log(fEpsilon));

    fYOut = fYoutTemp;
    // [/step 5]
}
// [/step 2]
