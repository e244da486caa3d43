// The scene key without the mip chain's error: the exact mean of level 0 of the luminance texture,
// computed on the GPU by a two-pass compute reduction (common/optional/shaders/ExactKey.comp) and written
// into the texture's 1x1 level, where the tutorial's final pass reads it.
//
// Why: glGenerateMipmap's filter is implementation-defined. At power-of-two sizes every level is an
// exact 2x2 average, but at odd sizes Mesa's reduction skips or down-weights rows and columns, so
// the 1x1 level is not the image's mean (at 1920x1080 the key Ya comes out about 1.5x too high).
#pragma once
#include "t10/gl_object.hpp"
#include "t10/shader.hpp"

namespace t10 {

class ExactKey {
public:
    // Compiles common/optional/shaders/ExactKey.comp through `shaders`.
    explicit ExactKey(const ShaderManager& shaders);

    // Averages level 0 (width x height, one channel, as the luminance pass wrote it) of `texture`
    // and stores the mean into level `lastLevel` (1x1) of the same texture, converted to its format
    // by GL as glTexSubImage2D converts a float. Stays on the GPU: nothing waits for the result.
    // Leaves the texture bindings, the active unit and the unpack buffer as it found them.
    void store(GLuint texture, int width, int height, int lastLevel);

    // Only the reduction (no store), for timing and tests: the mean stays in the result buffer.
    void reduce(GLuint texture, int width, int height);
    // Reads the mean of the last reduce() or store() back (waits for the GPU).
    float readMean() const;

private:
    Program program_;
    Buffer partials_;
    Buffer result_;
    GLsizeiptr partialsSize_ = 0;
};

} // namespace t10
