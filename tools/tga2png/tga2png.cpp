// tga2png: converts a TGA to PNG with the project's own loader (t10::loadTga) and PNG writer. Students
// and instructors use it to check a texture, or to check their own TGA loader against this one: if
// a file looks right here and wrong in a stage, the problem is in the upload, not the decoding.
// Exit codes: 0 done, 1 the file could not be read or written (the loader's message on stderr),
// 2 bad usage.
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/tga.hpp"

#include <cstring>
#include <iostream>

namespace {

void printUsage(std::ostream& out) {
    out << "usage: tga2png IN.tga OUT.png\n"
           "Decodes IN.tga with the Tutorial 10 TGA loader (types 2, 3, 10, 11; 8, 24 or 32 bits)\n"
           "and writes it as OUT.png. Exit status: 0 done, 1 unreadable input or unwritable output,\n"
           "2 bad usage.\n";
}

} // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            printUsage(std::cout);
            return 0;
        }
    }
    if (argc != 3 || argv[1][0] == '-' || argv[2][0] == '-') {
        std::cerr << "tga2png: expected an input .tga and an output .png\n";
        printUsage(std::cerr);
        return 2;
    }

    try {
        t10::writePng(argv[2], t10::loadTga(argv[1]));
    } catch (const t10::Error& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    return 0;
}
