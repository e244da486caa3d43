// Post-processing fragment shader: adds the bloom to the HDR accumulation colour, then tone maps
// it into the default framebuffer using the scene key averaged by the luminance pass
// (steps 6-10, 19-20). The exercises make the white point, the bloom switch (step 37) and the
// bloom's weight (step 38) uniforms, and skip the range mapping for a GL_R16F key (step 40).
#version 430 core

layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;
// [step 6] The luminance key texture
layout(binding = 16) uniform sampler2D s2LuminanceKeyTexture;
// [/step 6]
// [step 19] The bloom texture
layout(binding = 17) uniform sampler2D s2BloomTexture;
// [/step 19]

layout(location = 0) out vec3 v3ColourOut;

// [step 37] The white point Yw (it was the constant 0.22 of step 9) and the bloom switch
layout(location = 0) uniform float fYwhite;
layout(location = 3) uniform bool bBloom;
// [/step 37]
// [step 38] The weight the bloom is added with (it was the constant 0.98 of step 20)
layout(location = 1) uniform float fBloomStrength;
// [/step 38]
// [step 40] Range mapping on (GL_R16) or off (GL_R16F)
layout(location = 2) uniform bool bRangeMapping;
// [/step 40]

// [step 10] GLSL has no log10: log10(x) = log2(x) / log2(10)
float log10(in float fVal)
{
    // Log10(x) = log2(x) / log2(10)
    return log2(fVal) * 0.30102999566374217366165225171822f;
}
// [/step 10]

// [step 8] Tone mapping with the scene key
vec3 toneMap(vec3 v3RetColour, vec2 v2UV)
{
    // Get key luminance value (the huge bias clamps to the smallest, 1x1, mipmap level)
    float fYa = texture(s2LuminanceKeyTexture, v2UV, 1024).r;

    // [step 9] Undo the range mapping, then apply the tone map operator
    // Perform range mapping (optional: only needed with integer textures)
    const float fEpsilon = 0.00000001f;
    // [step 40] Only for the integer texture
    if (bRangeMapping) {
        fYa = (fYa * (log(fYwhite) - log(fEpsilon))) + log(fEpsilon);
    }
    // [/step 40]

    // Get exponent of log values
    fYa = exp(fYa);

    // Calculate middle-grey
    float fDg = 1.03f - (2.0f / (2.0f + log10(fYa + 1.0f)));

    // Calculate current luminance
    const vec3 v3LuminanceConvert = vec3(0.2126f, 0.7152f, 0.0722f);
    float fY = dot(v3RetColour, v3LuminanceConvert);

    // Calculate relative luminance
    float fYr = (fDg / fYa) * fY;

    // Calculate new luminance
    float fYNew = (fYr * (1.0f + (fYr / (fYwhite * fYwhite)))) / (1.0f + fYr);

    // Perform tone mapping; a black pixel would give 0 / 0 (NaN), so it stays black instead
    return (fY > 0.0f) ? v3RetColour * (fYNew / fY) : vec3(0.0f);
    // [/step 9]
}
// [/step 8]

// [step 20] Add the bloom, read from the smallest level the host allows (the bias clamps to it)
vec3 bloom(vec3 v3RetColour, vec2 v2UV)
{
    // Perform bloom addition
    vec3 v3Bloom = texture(s2BloomTexture, v2UV, 1024).rgb;
    // [step 38] The weight is a uniform
    return v3RetColour + (v3Bloom * fBloomStrength);
    // [/step 38]
}
// [/step 20]

void main() {
    // Get UV coordinates
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;

    // Get colour data
    vec3 v3RetColour = texture(s2AccumulationTexture, v2UV).rgb;

    // [step 20] Perform bloom before tone mapping
    // [step 37] unless it is switched off
    if (bBloom) {
        v3RetColour = bloom(v3RetColour, v2UV);
    }
    // [/step 37]
    // [/step 20]

    // [step 7] Perform tone map
    v3ColourOut = toneMap(v3RetColour, v2UV);
    // [/step 7]
}
