# Debug information by audience, for the Debug preset (make run, make test). The stages, the extras
# and common/ keep full -g: `make run` users step through them with locals. The programs that only the
# project's own checks run (tests/, tools/, grader/, tools/student/) are compiled with -g1: line tables
# and function names, so a backtrace or a sanitizer report still names file and line, without the
# type and variable information that made up most of their objects (make_gltf_fixtures' unity object:
# 8.8 MB and 6.3 CPU s with -g, 5.9 MB and 5.5 s with -g1). Their outputs are the same bits: only
# the debug sections differ. -DT10_FULL_DEBUG_INFO=ON gives them full -g for a debugging session.
option(T10_FULL_DEBUG_INFO "Full -g for the tests, tools and graders too (Debug builds)" OFF)

# -g1 (after CMAKE_CXX_FLAGS_DEBUG's -g, so it wins) on every compiled target of each folder, recursively.
function(t10_line_tables_only)
    if(T10_FULL_DEBUG_INFO OR NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
        return()
    endif()
    foreach(dir IN LISTS ARGN)
        get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
        foreach(target IN LISTS targets)
            get_target_property(type ${target} TYPE)
            if(type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
                target_compile_options(${target} PRIVATE $<$<CONFIG:Debug>:-g1>)
            endif()
        endforeach()
        get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
        if(subdirs)
            t10_line_tables_only(${subdirs})
        endif()
    endforeach()
endfunction()
