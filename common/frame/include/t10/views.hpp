// The view selector: shows one buffer of the tone mapping and bloom chain instead of the final
// frame (--view NAME headless, a key in the window, a list in the extras panel). It reads only what
// a stage leaves bound after its frame (units 15, 16 and 17) and the framebuffers it rendered
// through, so stage code stays as the tutorial writes it. The catalogue and the encodings are in
// view_catalogue.hpp, the discovery of the targets in view_targets.hpp; this is the service that
// draws (common/shaders/views/View.frag) and its options and keys.
#pragma once
#include "t10/keys.hpp"
#include "t10/view_catalogue.hpp"
#include "t10/view_targets.hpp"

#include <string>
#include <vector>

struct GLFWwindow;

namespace CLI {
class App;
}

namespace t10 {

class FullScreenQuad;
class ShaderManager;

struct ViewSettings {
    std::string view = "final"; // --view NAME, checked against t10::findView
    bool thumbnails = false;    // --thumbnails: the strip of every target under the frame
};

// Adds the "Views" group to `cli`; an unknown view name ends the parse with t10::UsageError.
void addViewOptions(CLI::App& cli, ViewSettings& settings);

class ViewService {
public:
    // `initial` must be a known view name (the command line checked it).
    ViewService(const ShaderManager& shaders, View initial);
    ~ViewService();
    ViewService(const ViewService&) = delete;
    ViewService& operator=(const ViewService&) = delete;

    // Draws the selected view (nothing for `final`) and the thumbnails over framebuffer 0. The
    // frame loop calls it after the stage's frame and before the UI. Throws t10::UsageError when the
    // stage lacks the view selected on the command line, listing the views it has.
    void draw(const FullScreenQuad& quad, int width, int height);

    View current() const { return current_; }
    // Views this stage has, as found in the last frame (before any frame: every view).
    bool available(View view) const;
    std::vector<View> availableViews() const;
    // Selects a view; false (and no change) if the stage lacks it.
    bool select(View view);
    // Moves to the next (+1) or previous (-1) view the stage has.
    void cycle(int direction);
    // The strip of thumbnails of every target along the bottom (window: T; --thumbnails).
    void showThumbnails(bool show) { thumbnails_ = show; }
    bool thumbnails() const { return thumbnails_; }
    // One line about what is shown: the view, its encoding, and its numbers (Ya, dg, counts).
    const std::string& caption() const { return caption_; }

private:
    void readKey();
    void countNonFinite();
    void updateCaption();
    void drawPass(View view, int x, int y, int width, int height, int legend) const;
    void drawThumbnails(int width, int height) const;

    const ShaderManager& shaders_;
    View current_;
    bool commandLineChecked_ = false;
    bool discovered_ = false;
    bool thumbnails_ = false;
    GLuint program_ = 0;
    ChainTargets chain_;
    double key_ = 0.0;
    std::string caption_;
    std::string printedCaption_;
};

// The window's keys for the views: V next, Shift+V previous, T thumbnails on and off.
class ViewKeys {
public:
    explicit ViewKeys(GLFWwindow* window) : window_(window) {}
    void update(ViewService& views);

private:
    GLFWwindow* window_;
    KeyEdges edges_;
};

} // namespace t10
