// The one translation unit holding tinygltf's code where it comes as a header only
// (cmake/T10HeaderOnly.cmake); Debian's libtinygltf-dev ships it as a shared library instead. stb's
// code is in stb_impl.cpp, so only the declarations are included here.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
