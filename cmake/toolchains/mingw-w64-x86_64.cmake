# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix: the POSIX
# thread model, which std::thread and std::mutex need). Used by `make windows-check`
# (tools/windows_check/), which builds the libraries Debian has no MinGW package of into
# T10_WINDOWS_PREFIX and runs the programs under Wine.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

# The prefix is passed down to every try_compile and to the libraries' own builds.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES T10_WINDOWS_PREFIX)
if(NOT T10_WINDOWS_PREFIX)
    set(T10_WINDOWS_PREFIX $ENV{T10_WINDOWS_PREFIX})
endif()
# Headers, libraries and CMake packages only from MinGW's own tree and that prefix: never Linux's.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${T10_WINDOWS_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config must not answer with Linux's packages: only the prefix's own .pc files (none are needed;
# stb and tinygltf are then found as headers, as with vcpkg).
set(ENV{PKG_CONFIG_LIBDIR} "${T10_WINDOWS_PREFIX}/lib/pkgconfig:${T10_WINDOWS_PREFIX}/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")

# Self-contained programs: libgcc, libstdc++ and winpthread linked in, so Wine (or a Windows
# machine) needs no MinGW DLLs next to them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(ZLIB_USE_STATIC_LIBS ON)
# ctest and add_custom_command run the programs through Wine.
find_program(T10_WINE NAMES wine)
if(T10_WINE)
    set(CMAKE_CROSSCOMPILING_EMULATOR ${T10_WINE})
endif()
