# OpenEXR, found once for the root project and for fuzz/: OpenEXR 3 (Debian 12 and 13, Ubuntu 24.04,
# vcpkg) or 2.5 (Ubuntu 22.04, Gradescope's default image). The code uses only the Imf API both have
# (RgbaInputFile, RgbaOutputFile, IStream, Header); what differs is the CMake package: 3 exports
# OpenEXR::OpenEXR with Imath 3 beside it, 2.5 exports OpenEXR::IlmImf with IlmBase's Half and Imath,
# its headers (Imath's too) in include/OpenEXR. Every target here links OpenEXR::OpenEXR, made an alias
# of 2.5's library where that is the one found.
find_package(OpenEXR REQUIRED)
if(OpenEXR_VERSION VERSION_LESS 2.5)
    message(FATAL_ERROR "OpenEXR ${OpenEXR_VERSION} is too old: 2.5 or 3 is needed (Debian: libopenexr-dev)")
endif()
if(NOT TARGET OpenEXR::OpenEXR)
    if(NOT TARGET OpenEXR::IlmImf)
        message(FATAL_ERROR "OpenEXR ${OpenEXR_VERSION}: its CMake package has neither OpenEXR::OpenEXR (3) "
                            "nor OpenEXR::IlmImf (2.5)")
    endif()
    # An alias of a non-global imported target is seen in this folder and below: include this file
    # from the top-level CMakeLists.txt.
    add_library(OpenEXR::OpenEXR ALIAS OpenEXR::IlmImf)
endif()
message(STATUS "OpenEXR ${OpenEXR_VERSION}")
