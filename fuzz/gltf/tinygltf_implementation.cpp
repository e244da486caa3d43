// tinygltf's and stb_image's code, compiled into the fuzzer with its instrumentation (the rest of
// the project links Debian's shared libtinygltf and libstb instead).
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
