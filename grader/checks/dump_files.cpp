// Reading a dump folder into a case's buffers; see dump_files.hpp.
#include "checks/dump_files.hpp"

#include "t10/image_io.hpp"
#include "t10/outputs.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace t10::grade {

namespace {

// <dir>/blur_passes.txt and its blur_passNN.pfm; false when the program did not capture (no file).
bool loadPasses(const std::string& dir, std::vector<CapturedPass>& passes) {
    std::ifstream list(dir + "/blur_passes.txt");
    if (!list) return false;
    for (std::string line; std::getline(list, line);) {
        std::istringstream fields(line);
        int index = 0;
        CapturedPass pass;
        fields >> index >> pass.subroutine;
        char file[32];
        std::snprintf(file, sizeof(file), "blur_pass%02d.pfm", index);
        pass.image = t10::readPfm(dir + "/" + file);
        passes.push_back(std::move(pass));
    }
    return true;
}

} // namespace

CaseBuffers loadCaseBuffers(const std::string& dir) {
    CaseBuffers buffers;
    buffers.name = dir;
    const auto path = [&](const std::string& file) { return dir + "/" + file; };
    buffers.accumulation = t10::readPfm(path(t10::dumpFileName(t10::contract::kAccumulationUnit, 0)));
    buffers.frame = t10::readPng(path("frame.png"));
    for (const int unit : {kLuminanceUnit, kBloomUnit}) {
        std::vector<BufferLevel>& levels = buffers.units[unit];
        for (int level = 0;; ++level) {
            const std::string file = path(t10::dumpFileName(static_cast<unsigned>(unit), level));
            if (!std::filesystem::exists(file)) break;
            BufferLevel read;
            try {
                read.image = t10::readPfm(file);
            } catch (...) {
                read.fault = std::current_exception();
            }
            levels.push_back(std::move(read));
        }
    }
    try {
        buffers.captured = loadPasses(dir, buffers.passes);
    } catch (...) {
        buffers.passesFault = std::current_exception();
    }
    return buffers;
}

} // namespace t10::grade
