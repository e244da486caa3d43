// Post-processing fragment shader: tone maps the HDR accumulation texture into the default
// framebuffer using the scene key averaged by the luminance pass (steps 6-10).
#version 430 core

layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;
// [step 6] The luminance key texture
layout(binding = 16) uniform sampler2D s2LuminanceKeyTexture;
// [/step 6]

layout(location = 0) out vec3 v3ColourOut;

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
    // Declared first: the tutorial's snippet uses fYwhite before its declaration, which does not compile
    const float fYwhite = 0.22f;

    // Perform range mapping (optional: only needed with integer textures)
    const float fEpsilon = 0.00000001f;
    fYa = (fYa * (log(fYwhite) - log(fEpsilon))) + log(fEpsilon);

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

void main() {
    // Get UV coordinates
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;

    // Get colour data
    vec3 v3RetColour = texture(s2AccumulationTexture, v2UV).rgb;

    // [step 7] Perform tone map
    v3ColourOut = toneMap(v3RetColour, v2UV);
    // [/step 7]
}
