// The one translation unit holding stb_image's and stb_image_write's code where stb comes as headers
// only (cmake/T10HeaderOnly.cmake); Debian's libstb-dev ships it compiled instead.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
