# The tests of a Windows build (MSVC with vcpkg, or the MinGW-w64 cross build that `make
# windows-check` runs under Wine): the unit and GL tests, each stage's golden comparison with its
# proof that an altered image fails, extras' frame against Part 3's, and students' parts. Included
# from tests/CMakeLists.txt on WIN32 only.
#
# Cross-compiled, the Catch2 programs run once each (their tests are listed at run time, where
# discovery would need Wine at build time); ctest starts them through CMAKE_CROSSCOMPILING_EMULATOR.
if(CMAKE_CROSSCOMPILING)
    add_test(NAME "unit: all" COMMAND t10_unit_tests)
    add_test(NAME "gl: all" COMMAND t10_gl_tests)
else()
    catch_discover_tests(t10_unit_tests TEST_PREFIX "unit: ")
    catch_discover_tests(t10_gl_tests TEST_PREFIX "gl: ")
endif()

# The golden settings are tests/golden/render_args.sh's (one place for both systems), with Windows'
# headless backend in place of EGL.
set(GOLDEN ${CMAKE_CURRENT_SOURCE_DIR}/golden)
file(READ ${GOLDEN}/render_args.sh render_args)
if(NOT render_args MATCHES "T10_GOLDEN_ARGS=\\(([^)]*)\\)")
    message(FATAL_ERROR "tests/golden/render_args.sh: no T10_GOLDEN_ARGS=(...) line")
endif()
string(REPLACE "--backend egl" "--backend wgl" golden_args "${CMAKE_MATCH_1}")
separate_arguments(golden_args UNIX_COMMAND "${golden_args}")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${GOLDEN}/render_args.sh)

foreach(stage IN LISTS T10_GOLDEN_STAGES)
    add_test(NAME "golden: ${stage}"
             COMMAND ${CMAKE_COMMAND} "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}"
                     -DSTAGE=$<TARGET_FILE:${stage}> -DIMGCOMPARE=$<TARGET_FILE:imgcompare>
                     -DGOLDEN=${GOLDEN}/${stage} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/out/golden/${stage}
                     "-DARGS=${golden_args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/golden/golden_test.cmake)
    # A visibly altered copy of the stage's own golden must fail.
    add_test(NAME "golden rejects: ${stage} altered"
             COMMAND imgcompare ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.tolerance
                     --alter --expect-reject)
endforeach()

# extras/ with default settings renders exactly Part 3's frame (as on Linux, stage_tests.cmake).
if(TARGET extras)
    add_test(NAME "golden: extras reproduces tutorial10_part3_gaussian"
             COMMAND ${CMAKE_COMMAND} "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}"
                     -DSTAGE=$<TARGET_FILE:extras> -DIMGCOMPARE=$<TARGET_FILE:imgcompare>
                     -DGOLDEN=${GOLDEN}/tutorial10_part3_gaussian -DOUT=${CMAKE_CURRENT_BINARY_DIR}/out/golden/extras
                     "-DARGS=${golden_args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/golden/golden_test.cmake)
endif()

# A student's own part (student/partN/, cmake/T10Student.cmake) against Part N's golden: how a Windows
# student checks their work without the Linux-only grader. The program is built on demand
# (cmake --build build --target student_partN); the test says so when it is missing.
set(part_stages tutorial10_part1_tonemap tutorial10_part2_bloom tutorial10_part3_gaussian)
foreach(part 1 2 3)
    if(NOT TARGET student_part${part})
        continue()
    endif()
    math(EXPR index "${part} - 1")
    list(GET part_stages ${index} golden_stage)
    add_test(NAME "student: student_part${part} against ${golden_stage}'s golden"
             COMMAND ${CMAKE_COMMAND} "-DEMULATOR=${CMAKE_CROSSCOMPILING_EMULATOR}"
                     -DSTAGE=$<TARGET_FILE:student_part${part}> -DIMGCOMPARE=$<TARGET_FILE:imgcompare>
                     -DGOLDEN=${GOLDEN}/${golden_stage} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/out/student/part${part}
                     "-DARGS=${golden_args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/golden/golden_test.cmake)
endforeach()
