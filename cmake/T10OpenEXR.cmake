# OpenEXR, found once for the root project and for fuzz/: OpenEXR 3 (Debian 12 and 13, Ubuntu 24.04,
# vcpkg) or 2.5 (Ubuntu 22.04, Gradescope's default image). The code uses only the Imf API both have
# (RgbaInputFile, RgbaOutputFile, IStream, Header); what differs is the CMake package: 3 exports
# OpenEXR::OpenEXR with Imath 3 beside it, 2.5 exports OpenEXR::IlmImf with IlmBase's Half and Imath,
# its headers (Imath's too) in include/OpenEXR. Every target here links OpenEXR::OpenEXR, made an alias
# of 2.5's library where that is the one found.
#
# Debian 12's libimath-dev exports PyImath's library (Imath::PyImath_Python3_11) beside Imath's but
# ships it in python3-imath, which nothing here needs; its ImathTargets.cmake then prints a
# ten-line "... but this file does not exist" for it at every fresh configure, which reads as a
# failure. Imath is found first with that file's STATUS messages off (warnings and errors still
# print), and the one library this project links through OpenEXR, Imath::Imath, is checked here
# instead; OpenEXR's own find_dependency(Imath) then reuses the targets without loading them again.
if(NOT TARGET Imath::Imath)
    set(t10_message_log_level "${CMAKE_MESSAGE_LOG_LEVEL}")
    set(CMAKE_MESSAGE_LOG_LEVEL NOTICE)
    find_package(Imath CONFIG QUIET)
    set(CMAKE_MESSAGE_LOG_LEVEL "${t10_message_log_level}")
    unset(t10_message_log_level)
    if(TARGET Imath::Imath)
        get_target_property(t10_imath_configs Imath::Imath IMPORTED_CONFIGURATIONS)
        foreach(t10_config IN LISTS t10_imath_configs)
            get_target_property(t10_imath_file Imath::Imath IMPORTED_LOCATION_${t10_config})
            if(t10_imath_file AND NOT EXISTS "${t10_imath_file}")
                message(WARNING "Imath's CMake package (${Imath_DIR}) names the library ${t10_imath_file}, which does "
                                "not exist: reinstall libimath-dev (Debian) or Imath")
            endif()
        endforeach()
        unset(t10_imath_configs)
        unset(t10_imath_file)
        unset(t10_config)
    endif()
endif()
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
