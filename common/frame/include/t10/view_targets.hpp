// Finding the chain's targets after a stage's frame, from GL state alone: the textures the stage left
// bound on units 15-17 (contract.hpp), their levels, and the blur intermediate among the
// framebuffers' colour attachments. Stage code stays as the tutorial writes it.
#pragma once
#include "t10/gl.hpp"
#include "t10/view_catalogue.hpp"

#include <cstddef>
#include <string>

namespace t10 {

// A target of the chain as found after the stage's frame.
struct ViewTarget {
    GLuint texture = 0;
    int level = 0;
    int width = 0;
    int height = 0;
    GLint format = 0;
};

// Every target a view can show, as found after the stage's frame (texture 0: not there).
struct ChainTargets {
    ViewTarget accumulation;
    ViewTarget luminance;
    ViewTarget luminanceSmallest;
    ViewTarget bloom0;
    ViewTarget bloom1;
    ViewTarget blur;
    bool luminanceMapped = true; // GL_R16 holds the range-mapped value, GL_R16F (exercise 40) the log
    double ywhite = views::kYwhite; // the final program's fYwhite uniform (extras), else the tutorial's
};

namespace views {
// The view pass samples single-level texture views on units no stage touches: accumulation,
// luminance, bloom0, bloom1 and blur from kFirstViewUnit on; discovery inspects textures on the next.
constexpr GLuint kFirstViewUnit = 18;
constexpr int kSampledTargets = 5;
constexpr GLuint kQueryUnit = kFirstViewUnit + kSampledTargets;
} // namespace views

// Finds the targets for a framebuffer `width` x `height`; leaves the active unit and the read
// framebuffer as they were.
ChainTargets discoverChain(int width, int height);

// Texels of `target` with a NaN or infinite channel (read back; `rgba` for four channels).
std::size_t countNonFiniteTexels(const ViewTarget& target, bool rgba);

// "GL_RGBA16F level 0, 160x90", for captions; formatName alone for labels.
std::string formatName(GLint format);
std::string describe(const ViewTarget& target);

} // namespace t10
