// Tutorial 10 steps 8-9 as the tutorial prints them: fYwhite used before its declaration, and a
// black pixel divided 0 / 0 (the reference declares fYwhite first and keeps black pixels black).
// Template for the similarity check; never compiled.
vec3 toneMap(vec3 v3RetColour, vec2 v2UV)
{
    // Get key luminance value
    float fYa = texture(s2LuminanceKeyTexture, v2UV, 1024).r;

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
    const float fYwhite = 0.22f;
    float fYNew = (fYr * (1.0f + (fYr / (fYwhite * fYwhite)))) / (1.0f + fYr);

    // Perform tone mapping
    return v3RetColour * (fYNew / fY);
}
