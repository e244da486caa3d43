// A case of t10-grade rendered in the running page (the web build only: case_capture_web.cpp), for the
// page's check (grader/page/): the case's frame and buffers written into the page's file system exactly
// as a binary's --dump and --output write them, so that t10-grade's own dump reader and checks read them.
#pragma once
#include <string>
#include <vector>

namespace t10 {

// Renders one frame of the page's stage with the page's command line plus `args` (a case's --size and
// --camera) and writes, into the folder `dir` of the page's file system, what `--dump DIR --output
// DIR/frame.png` writes after a binary's last frame: the frame, every level of the textures on units
// 15-17; with `passes`, each blur pass as --capture-passes DIR writes it (the draws observed through
// the platform's GL layer). The page's own settings are put back afterwards and a frame of them asked
// for. Throws t10::Error when no stage runs, an argument is refused or a file cannot be written.
void capturePageCase(const std::vector<std::string>& args, const std::string& dir, bool passes);

// The running page's stage (its folder's name: tutorial10_part1_tonemap, student_part2), or "".
std::string pageStageName();

} // namespace t10
