// libFuzzer target: the TGA loader (decodeTga) on arbitrary bytes. A decoded image must be
// consistent with its size; an error must be a t10::Error naming the input (anything else escapes
// and is a finding). Sanitizers catch the rest.
#include "t10/error.hpp"
#include "t10/tga.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const t10::Image8 image = t10::decodeTga(data, size, "fuzz.tga");
        const bool channelsOk = image.channels == 1 || image.channels == 3 || image.channels == 4;
        const bool sizeOk = image.width >= 1 && image.height >= 1 && image.width <= t10::kTgaMaxSide &&
                            image.height <= t10::kTgaMaxSide;
        if (!channelsOk || !sizeOk ||
            image.data.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                     static_cast<std::size_t>(image.channels))
            __builtin_trap();
    } catch (const t10::Error& error) {
        if (std::string(error.what()).rfind("fuzz.tga: ", 0) != 0) __builtin_trap(); // names the file
    }
    return 0;
}
