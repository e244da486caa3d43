// The capture hook of the frame loop: a FrameObserver sees each frame's GL_Render begin, every draw
// call the stage makes inside it, and its end, without a change to the stage's code. App calls it
// (App::setObserver, or --capture-passes for the built-in PassCapture); tools such as t10-grade use it
// to look at buffers that the frame overwrites before --dump could read them (each blur pass).
#pragma once
#include <memory>
#include <string>

namespace t10 {

class FrameObserver {
public:
    virtual ~FrameObserver() = default;
    // Before the stage's render, inside its pass timers.
    virtual void beginRender() {}
    // Right after each glDrawElements / glDrawArrays of the stage's render returned; the GL state is
    // the draw's (program, framebuffer, subroutines), so the observer may query and read it back,
    // but must leave every binding it changes as it found it.
    virtual void afterDraw() {}
    // After the stage's render returned.
    virtual void endRender() {}
};

// While alive, every glDrawElements and glDrawArrays called through the loader is followed by
// observer.afterDraw(). App holds one around the stage's render only: draws of the views, the UI
// or the bench's own code are not observed. One at a time (t10::Error for a second one): GL entry
// points are plain function pointers, so the observer is found through one per-process slot.
class DrawObservation {
public:
    explicit DrawObservation(FrameObserver& observer);
    ~DrawObservation();
    DrawObservation(const DrawObservation&) = delete;
    DrawObservation& operator=(const DrawObservation&) = delete;
};

// The built-in observer of --capture-passes DIR: after each draw into a texture (the draw
// framebuffer's colour attachment 0) by a program with fragment subroutine uniforms (Part 3's
// Gaussian program, Gauss.frag's SampleOffset), the texture level drawn into is read back into
// DIR/blur_passNN.pfm (NN from 01) and listed in DIR/blur_passes.txt, one line per pass:
//   <pass> <subroutine name> <texture> <level> <width>x<height>
// Every frame rewrites them, so after the run they describe the last frame, like --dump.
std::unique_ptr<FrameObserver> makePassCapture(const std::string& dir);

} // namespace t10
