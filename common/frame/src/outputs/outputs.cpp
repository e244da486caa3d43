// The output files of a run; see outputs.hpp.
#include "t10/outputs.hpp"

#include "t10/args.hpp"
#include "t10/cli_range.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/readback.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>

namespace t10 {

namespace {

// `option` names the command-line option in the message ("--output FILE: cannot create ...").
void createParentDirectory(const std::string& option, const std::string& file) {
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    std::error_code error;
    if (!parent.empty()) std::filesystem::create_directories(parent, error);
    if (error)
        throw Error(option + " " + file + ": cannot create folder " + parent.string() + ": " + error.message());
}

void writeDump(const std::string& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) throw Error("--dump " + dir + ": cannot create folder " + dir + ": " + error.message());
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (GLuint unit : contract::kPostProcessUnits) {
        glActiveTexture(GL_TEXTURE0 + unit);
        GLint texture = 0;
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
        if (texture == 0) continue;
        GLint levels = 0;
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        for (int level = 0; level < std::max(levels, 1); ++level) {
            const std::string file = (std::filesystem::path(dir) / dumpFileName(unit, level)).string();
            writePfm(file, readTextureLevel(static_cast<GLuint>(texture), level));
        }
    }
    glActiveTexture(static_cast<GLenum>(active));
    std::cout << "wrote textures of units " << contract::kAccumulationUnit << "-" << contract::kBloomUnit << " into "
              << dir << "\n";
}

} // namespace

std::string dumpFileName(unsigned unit, int level) {
    return "unit" + std::to_string(unit) + "_level" + std::to_string(level) + ".pfm";
}

void addOutputOptions(CLI::App& cli, OutputSettings& settings) {
    CLI::Option_group* group = cli.add_option_group("Outputs", "Files written after the last frame");
    CLI::Option* output = group->add_option("--output", settings.output,
                                            "Write the final frame as an 8-bit PNG (exactly what the window shows)");
    CLI::Option* exr = group->add_option("--exr", settings.exr,
                                         "Write the HDR accumulation buffer as an OpenEXR file (RGBA half)");
    CLI::Option* dump = group->add_option("--dump", settings.dumpDir,
                                          "After the last frame, write every level of the textures on units "
                                          "15-17 (contract.hpp) as PFM files into DIR (for numeric checks)");
    CLI::Option* capture = group->add_option("--capture-passes", settings.capturePassesDir,
                                             "During every frame, write each Gaussian blur pass as it is drawn into DIR "
                                             "(blur_passNN.pfm, listed in blur_passes.txt; for t10-grade)");
    group->callback([&settings, output, exr, dump, capture] {
        refuseEmpty({output, exr, dump, capture});
        if (!settings.output.empty() && !hasSuffix(settings.output, ".png")) {
            throw UsageError("--output " + settings.output + ": the file name must end in .png");
        }
        if (!settings.exr.empty() && !hasSuffix(settings.exr, ".exr")) {
            throw UsageError("--exr " + settings.exr + ": the file name must end in .exr");
        }
    });
}

bool wantsOutputs(const OutputSettings& options) {
    return !options.output.empty() || !options.exr.empty() || !options.dumpDir.empty();
}

void writeOutputs(const OutputSettings& options, int width, int height, const Scene& scene) {
    if (!options.output.empty()) {
        if (width == 0 || height == 0) throw Error(options.output + ": not written, the last frame was 0x0");
        createParentDirectory("--output", options.output);
        writePng(options.output, readDefaultFramebuffer(width, height));
        std::cout << "wrote " << options.output << "\n";
    }
    if (!options.exr.empty()) {
        if (width == 0 || height == 0) throw Error(options.exr + ": not written, the last frame was 0x0");
        createParentDirectory("--exr", options.exr);
        writeExr(options.exr, readTextureLevel(scene.accumulationTexture(), 0, true));
        std::cout << "wrote " << options.exr << "\n";
    }
    if (!options.dumpDir.empty()) writeDump(options.dumpDir);
}

} // namespace t10
