// The view selector's pass (common/frame/src/views/views.cpp): draws one buffer of the chain over framebuffer
// 0. Each sampler holds a single-level texture view; each framebuffer pixel reads the texel at
// pixel * texture size / framebuffer size (integer division), so a half-size level shows as 2x2
// blocks and a test can find the texel behind every pixel. The encodings mirror t10::views.
#version 430 core

layout(binding = 18) uniform sampler2D s2Accumulation;
layout(binding = 19) uniform sampler2D s2Luminance;
layout(binding = 20) uniform sampler2D s2Bloom0;
layout(binding = 21) uniform sampler2D s2Bloom1;
layout(binding = 22) uniform sampler2D s2Blur;

layout(location = 0) uniform int iMode; // t10::View
layout(location = 1) uniform ivec2 i2Size;
layout(location = 2) uniform float fExposure;
layout(location = 3) uniform float fKeyPosition; // the key on the colour scale
layout(location = 4) uniform float fKey;         // Ya
layout(location = 5) uniform float fDg;
layout(location = 6) uniform float fYwhite;
layout(location = 7) uniform int iMapped; // 1: the luminance texture holds range-mapped values
layout(location = 8) uniform int iLegend; // legend strip height in pixels
layout(location = 9) uniform int iPresent; // bit i: target i is bound (accumulation, luminance, bloom0, bloom1, blur)
layout(location = 10) uniform vec3 v3Scale[7];
layout(location = 17) uniform ivec2 i2Origin; // the pass's viewport corner (thumbnails)
layout(location = 18) uniform int iTextScale;
layout(location = 19) uniform int iText[24]; // label glyphs (index into kFont, -1: none)

out vec3 v3ColourOut;

const int kHdr = 1, kLuminance = 2, kKey = 3, kBloom0 = 4, kBloom1 = 5, kBlur = 6, kEv = 7, kNan = 8;
const int kEvLowest = -6;
const int kEvHighest = 5;
const float kEvScaleTop = 5.0 / 6.0; // the bands stop at red: white means burnt
const float kEpsilon = 1e-8;
const vec3 v3LuminanceConvert = vec3(0.2126, 0.7152, 0.0722);

// A 3x5 font for the thumbnail labels, "0123456789xRGBAF_ " (t10::views kGlyphChars): 15 bits per
// glyph, the top row in the highest three.
const int kFont[18] = int[18](0x7B6F, 0x2C97, 0x73E7, 0x73CF, 0x5BC9, 0x79CF, 0x79EF, 0x7249, 0x7BEF, 0x7BCF,
                              0x0AA8, 0x6BAD, 0x796F, 0x6BAE, 0x2BED, 0x79A4, 0x0007, 0x0000);

vec4 fetch(sampler2D s)
{
    ivec2 i2TexSize = textureSize(s, 0);
    ivec2 i2Texel = (ivec2(gl_FragCoord.xy) - i2Origin) * i2TexSize / i2Size;
    return texelFetch(s, min(i2Texel, i2TexSize - 1), 0);
}

vec3 colourScale(float t)
{
    float x = clamp(t, 0.0, 1.0) * 6.0;
    int i = min(int(x), 5);
    return mix(v3Scale[i], v3Scale[i + 1], x - float(i));
}

vec3 display(vec3 v3Linear)
{
    return pow(clamp(v3Linear * fExposure, 0.0, 1.0), vec3(1.0 / 2.2));
}

// Inf and NaN have every exponent bit set (a bit test, which no optimiser folds away).
bool nonFinite(vec4 v)
{
    uvec4 u4Exponent = floatBitsToUint(v) & 0x7f800000u;
    return any(equal(u4Exponent, uvec4(0x7f800000u)));
}

vec3 evColour(float fY)
{
    float fYr = fDg / fKey * fY;
    if (fYr >= fYwhite) return vec3(1.0);
    float fDisplayed = fYr * (1.0 + fYr / (fYwhite * fYwhite)) / (1.0 + fYr);
    if (!(fDisplayed >= 0.5 / 255.0)) return vec3(0.0);
    int iStop = clamp(int(floor(log2(fY / fKey))), kEvLowest, kEvHighest);
    vec3 v3Band = colourScale(float(iStop - kEvLowest) / float(kEvHighest - kEvLowest) * kEvScaleTop);
    return fDisplayed > fY ? v3Band : 0.5 * v3Band;
}

vec3 evLegend(ivec2 i2Pixel)
{
    // Black, one segment per stop, white; the upper half lifted, the lower half compressed.
    int iSegments = kEvHighest - kEvLowest + 3;
    int iSegment = i2Pixel.x * iSegments / i2Size.x;
    if (iSegment == 0) return vec3(0.0);
    if (iSegment == iSegments - 1) return vec3(1.0);
    vec3 v3Band = colourScale(float(iSegment - 1) / float(kEvHighest - kEvLowest) * kEvScaleTop);
    return i2Pixel.y * 2 >= iLegend ? v3Band : 0.5 * v3Band;
}

// A label on a dark band: glyph cells 4 x 6 font pixels, one font pixel of margin.
vec3 label(ivec2 i2Pixel)
{
    ivec2 i2Font = i2Pixel / iTextScale - ivec2(1);
    int iChar = i2Font.x / 4;
    int iColumn = i2Font.x - iChar * 4;
    int iRow = 4 - i2Font.y; // from the top
    if (i2Font.x < 0 || iChar >= 24 || iColumn > 2 || iRow < 0 || iRow > 4) return vec3(0.1);
    int iGlyph = iText[iChar];
    if (iGlyph < 0) return vec3(0.1);
    return ((kFont[iGlyph] >> (14 - (iRow * 3 + iColumn))) & 1) != 0 ? vec3(1.0) : vec3(0.1);
}

void main() {
    ivec2 i2Pixel = ivec2(gl_FragCoord.xy) - i2Origin;
    bool bLegend = i2Pixel.y < iLegend;
    if (iMode == kHdr) {
        v3ColourOut = display(fetch(s2Accumulation).rgb);
    } else if (iMode == kLuminance) {
        float fValue = fetch(s2Luminance).r;
        float fT = iMapped == 1 ? fValue : (fValue - log(kEpsilon)) / (log(fYwhite) - log(kEpsilon));
        v3ColourOut = colourScale(bLegend ? (float(i2Pixel.x) + 0.5) / float(i2Size.x) : fT);
    } else if (iMode == kKey) {
        // The swatch; along the bottom the scale with the key's column marked, black over white.
        int iMarker = clamp(int(fKeyPosition * float(i2Size.x)), 0, i2Size.x - 1);
        if (!bLegend) v3ColourOut = colourScale(fKeyPosition);
        else if (i2Pixel.x == iMarker) v3ColourOut = i2Pixel.y * 2 >= iLegend ? vec3(0.0) : vec3(1.0);
        else v3ColourOut = colourScale((float(i2Pixel.x) + 0.5) / float(i2Size.x));
    } else if (iMode == kBloom0) {
        v3ColourOut = display(fetch(s2Bloom0).rgb);
    } else if (iMode == kBloom1) {
        v3ColourOut = display(fetch(s2Bloom1).rgb);
    } else if (iMode == kBlur) {
        v3ColourOut = display(fetch(s2Blur).rgb);
    } else if (iMode == kEv) {
        v3ColourOut = bLegend ? evLegend(i2Pixel) : evColour(dot(fetch(s2Accumulation).rgb, v3LuminanceConvert));
    } else if (iMode == kNan) {
        vec4 v4Colour = fetch(s2Accumulation);
        bool bBad = nonFinite(v4Colour);
        if ((iPresent & 2) != 0) bBad = bBad || nonFinite(fetch(s2Luminance));
        if ((iPresent & 4) != 0) bBad = bBad || nonFinite(fetch(s2Bloom0));
        if ((iPresent & 8) != 0) bBad = bBad || nonFinite(fetch(s2Bloom1));
        if ((iPresent & 16) != 0) bBad = bBad || nonFinite(fetch(s2Blur));
        v3ColourOut = bBad ? vec3(1.0, 0.0, 1.0) : 0.5 * display(v4Colour.rgb);
    } else {
        v3ColourOut = label(i2Pixel);
    }
}
