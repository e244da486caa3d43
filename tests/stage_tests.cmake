# ctest entries that run the built programs: golden images, rejection proofs, backends, window mode,
# resizes, the command line and the tools. Included from tests/CMakeLists.txt.
set(EXPECT ${CMAKE_CURRENT_SOURCE_DIR}/expect.sh)
set(GOLDEN ${CMAKE_CURRENT_SOURCE_DIR}/golden)
set(GOLDEN_TEST ${GOLDEN}/golden_test.sh)
set(GOLDEN_ARGS --backend egl --size 640x360 --camera default --frames 1)
find_program(XVFB_RUN xvfb-run)

# --- Per stage: --help, the golden image and proof that it rejects a wrong image, the stage rule. -----
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(STAGE_DIFF ${CMAKE_CURRENT_SOURCE_DIR}/stage_diff.py)

# t10_add_stage_tests(<stage> [AFTER <previous stage> STEPS <first> <last>] [SAME_GOLDEN_AS <stage>])
# AFTER/STEPS: the stage adds exactly those tutorial steps to <previous stage> (tests/stage_diff.py),
# and <previous stage>'s image must fail this stage's golden. SAME_GOLDEN_AS: a program whose
# default frame must equal another stage's golden (extras/ with default settings renders Part 3).
function(t10_add_stage_tests stage)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "AFTER;SAME_GOLDEN_AS" "STEPS")
    add_test(NAME "cli: ${stage} --help"
             COMMAND ${EXPECT} 0 "--camera TEXT" -- ${BIN}/${stage} --help)
    if(ARG_AFTER)
        list(JOIN ARG_STEPS "-" range)
        add_test(NAME "stage diff: ${ARG_AFTER} -> ${stage} holds only steps ${range}"
                 COMMAND ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${STAGE_DIFF} ${PROJECT_SOURCE_DIR}/${ARG_AFTER}
                         ${PROJECT_SOURCE_DIR}/${stage} ${ARG_STEPS})
    endif()
    if(ARG_SAME_GOLDEN_AS)
        add_test(NAME "golden: ${stage} reproduces ${ARG_SAME_GOLDEN_AS}"
                 COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/golden ${stage} --golden ${ARG_SAME_GOLDEN_AS})
        return()
    endif()
    add_test(NAME "golden: ${stage}" COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/golden ${stage})
    # A visibly altered copy of the stage's own golden must fail.
    add_test(NAME "golden rejects: ${stage} altered"
             COMMAND ${BIN}/imgcompare ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.tolerance
                     --alter --expect-reject)
    # The previous stage's image must fail this stage's golden.
    if(ARG_AFTER)
        add_test(NAME "golden rejects: ${ARG_AFTER} as ${stage}"
                 COMMAND ${BIN}/imgcompare ${GOLDEN}/${stage}.png ${GOLDEN}/${ARG_AFTER}.png
                         ${GOLDEN}/${stage}.tolerance --expect-reject)
    endif()
endfunction()

t10_add_stage_tests(tutorial10_part0_start)
t10_add_stage_tests(tutorial10_part1_tonemap AFTER tutorial10_part0_start STEPS 1 16)
t10_add_stage_tests(tutorial10_part2_bloom AFTER tutorial10_part1_tonemap STEPS 17 25)
t10_add_stage_tests(tutorial10_part3_gaussian AFTER tutorial10_part2_bloom STEPS 26 36)
if(TARGET extras)
    t10_add_stage_tests(extras AFTER tutorial10_part3_gaussian STEPS 37 40 SAME_GOLDEN_AS tutorial10_part3_gaussian)
endif()
# The check can fail: Part 2 measured against Part 1's step range holds steps 17-25 too many.
add_test(NAME "stage diff: rejects steps of another part"
         COMMAND ${EXPECT} 1 "not part of steps 1-16" -- ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${STAGE_DIFF}
                 ${PROJECT_SOURCE_DIR}/tutorial10_part0_start ${PROJECT_SOURCE_DIR}/tutorial10_part2_bloom 1 16)

# A malformed marker is a problem too (the parser is tools/markers, shared with the site).
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/marker_check/old/Tutorial10.cpp "int a;\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/marker_check/new/Tutorial10.cpp "int a;\n// [step 1] b\nint b;\n")
add_test(NAME "stage diff: rejects a step block that is never closed"
         COMMAND ${EXPECT} 1 "\\[step 1\\] is never closed" -- ${T10_PYTHON_ENV} ${Python3_EXECUTABLE} ${STAGE_DIFF}
                 ${CMAKE_CURRENT_BINARY_DIR}/marker_check/old ${CMAKE_CURRENT_BINARY_DIR}/marker_check/new 1 1)

# --- make help names every target of the Makefile and every `make NAME` of the README. ----------
set(MAKE_HELP ${CMAKE_CURRENT_SOURCE_DIR}/make_help.py)
add_test(NAME "make help: lists every target" COMMAND ${EXPECT} 0 "ok: make help lists all" --
         ${Python3_EXECUTABLE} ${MAKE_HELP} ${PROJECT_SOURCE_DIR})
# The check can fail: a copy of the Makefile whose help lost the line of `make fuzz`.
file(READ ${PROJECT_SOURCE_DIR}/Makefile makefile_text)
string(REGEX REPLACE "\t@echo \"make fuzz  [^\n]*\n" "" makefile_text "${makefile_text}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/make_help_check/Makefile "${makefile_text}")
file(COPY ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_CURRENT_BINARY_DIR}/make_help_check)
add_test(NAME "make help: the check rejects a missing target"
         COMMAND ${EXPECT} 1 "make help does not list `make fuzz`" --
                 ${Python3_EXECUTABLE} ${MAKE_HELP} ${CMAKE_CURRENT_BINARY_DIR}/make_help_check)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/Makefile ${PROJECT_SOURCE_DIR}/README.md)

# --- Layers: the folders of common/ are its layers; each includes only the ones below it. -------
set(LAYERS ${CMAKE_CURRENT_SOURCE_DIR}/layers.py)
set(T10_LAYER_FOLDERS base platform content frame optional panel)
add_test(NAME "layers: common/ folders include only the layers below them, no file cycle"
         COMMAND ${EXPECT} 0 "layers respected, no cycle" -- ${Python3_EXECUTABLE} ${LAYERS} ${PROJECT_SOURCE_DIR}/common)
# The check can fail: copies of common/'s code with one include changed, each of which must be
# reported with its file and line (or its cycle).
# t10_add_layer_mutant(<name> <file under common/> <include line, put first in the file> <regex>)
function(t10_add_layer_mutant name file line regex)
    string(MAKE_C_IDENTIFIER "${name}" folder)
    set(root ${CMAKE_CURRENT_BINARY_DIR}/layers_check/${folder})
    file(REMOVE_RECURSE ${root})
    foreach(layer IN LISTS T10_LAYER_FOLDERS)
        file(COPY ${PROJECT_SOURCE_DIR}/common/${layer} DESTINATION ${root})
    endforeach()
    file(READ ${PROJECT_SOURCE_DIR}/common/${file} source)
    file(WRITE ${root}/${file} "${line}\n${source}")
    add_test(NAME "layers: rejects ${name}"
             COMMAND ${EXPECT} 1 "${regex}" -- ${Python3_EXECUTABLE} ${LAYERS} ${root})
endfunction()
t10_add_layer_mutant("a header that includes a test's header" content/include/t10/scene.hpp
                     "#include \"dumps.hpp\"" "scene.hpp:1: includes \"dumps.hpp\", which is not a header of common/")
t10_add_layer_mutant("content that includes the frame layer" content/src/scene.cpp
                     "#include \"t10/app.hpp\"" "scene.cpp:1: includes \"t10/app.hpp\" of frame, a layer content may not include")
t10_add_layer_mutant("platform that includes content" platform/src/context.cpp
                     "#include \"t10/tga.hpp\"" "context.cpp:1: includes \"t10/tga.hpp\" of content")
t10_add_layer_mutant("stage.hpp that includes the command line" frame/include/t10/stage.hpp
                     "#include \"t10/cli.hpp\"" "stage.hpp:1: includes \"t10/cli.hpp\" of frame \\(stage.hpp may include only")
t10_add_layer_mutant("two files that need each other" frame/src/view_catalogue.cpp
                     "#include \"t10/views.hpp\"" "cycle between files: (view_catalogue -> views -> view_catalogue|views -> view_catalogue -> views)")
# grader/: its folders are the stages of its pipeline, checked the same way (layers.py --grader), and
# copies of grader/ with one include added must be reported.
add_test(NAME "layers: grader/ folders include only the stages before them, no file cycle"
         COMMAND ${EXPECT} 0 "stages respected, no cycle" -- ${Python3_EXECUTABLE} ${LAYERS} --grader
                 ${PROJECT_SOURCE_DIR}/grader ${PROJECT_SOURCE_DIR}/common)
function(t10_add_grader_layer_mutant name file line regex)
    string(MAKE_C_IDENTIFIER "grader ${name}" folder)
    set(root ${CMAKE_CURRENT_BINARY_DIR}/layers_check/${folder})
    file(REMOVE_RECURSE ${root})
    file(COPY ${PROJECT_SOURCE_DIR}/grader DESTINATION ${root} FILES_MATCHING PATTERN "*.hpp" PATTERN "*.cpp")
    file(READ ${PROJECT_SOURCE_DIR}/grader/${file} source)
    file(WRITE ${root}/grader/${file} "${line}\n${source}")
    add_test(NAME "layers: rejects grader ${name}"
             COMMAND ${EXPECT} 1 "${regex}" -- ${Python3_EXECUTABLE} ${LAYERS} --grader ${root}/grader ${PROJECT_SOURCE_DIR}/common)
endfunction()
t10_add_grader_layer_mutant("checks that include the report" checks/checks.hpp "#include \"report/report.hpp\""
                            "checks.hpp:1: includes \"report/report.hpp\" of report, a stage checks may not include")
t10_add_grader_layer_mutant("code that includes a test's header" checks/table.cpp "#include \"dumps.hpp\""
                            "table.cpp:1: includes \"dumps.hpp\", which is neither a header of common/ nor of the grader")
t10_add_grader_layer_mutant("a report that includes a platform's format" report/class_index.cpp
                            "#include \"platforms/formats.hpp\""
                            "class_index.cpp:1: includes \"platforms/formats.hpp\" of platforms, a stage report may not include")
t10_add_grader_layer_mutant("a compile that includes the capture after it" compile/build.cpp "#include \"capture/capture.hpp\""
                            "build.cpp:1: includes \"capture/capture.hpp\" of capture, a stage compile may not include")
# The checks' core (checks/, diagnosis/, part/ but for the dump reader, the catalogue's file and FLIP)
# runs on buffers in memory, for a page to compile (issue 49): a header of files or processes in it, or
# its include of an adapter, is reported; so is a grader file over 700 lines (table.cpp with 300 more).
t10_add_grader_layer_mutant("a core that includes <filesystem>" checks/table.cpp "#include <filesystem>"
                            "table.cpp:1: includes <filesystem>: the checks' core runs on buffers in memory")
t10_add_grader_layer_mutant("a core that includes the dump reader" checks/reconcile.cpp "#include \"checks/dump_files.hpp\""
                            "reconcile.cpp:1: includes \"checks/dump_files.hpp\", which is not the checks' core")
string(REPEAT "//\n" 300 many_lines)
t10_add_grader_layer_mutant("a file over 700 lines" checks/table.cpp "${many_lines}" "table.cpp: [0-9]+ lines, over 700")

# --- The facts of each part (its stage, its steps, its golden): grader/part/part.cpp describes them for
# the grader; the CMake, Python and shell that cannot include it are held to it (tests/part_facts.py).
# Shown to fail with Gradescope's setup.sh grading Part 2 against Part 3's stage.
set(PART_FACTS ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/part_facts.py ${PROJECT_SOURCE_DIR})
add_test(NAME "part facts: every copy agrees with the grader's part description"
         COMMAND ${EXPECT} 0 "they agree" -- ${PART_FACTS})
add_test(NAME "part facts: rejects a copy that disagrees"
         COMMAND ${EXPECT} 1 "setup.sh: the case of .T10_PART: .*'2': 'tutorial10_part3_gaussian'.*where grader/part/part.cpp says" -- ${PART_FACTS}
                 --replace grader/platforms/gradescope/setup.sh "2) stage=tutorial10_part2_bloom" "2) stage=tutorial10_part3_gaussian")

# --- Function length: no function over 120 lines outside stage files and data generators. --------
set(FUNCTION_LENGTH ${CMAKE_CURRENT_SOURCE_DIR}/function_length.py)
add_test(NAME "function length: nothing over 120 lines outside stages and data generators"
         COMMAND ${EXPECT} 0 "functions over 120 lines: 0" -- ${Python3_EXECUTABLE} ${FUNCTION_LENGTH} ${PROJECT_SOURCE_DIR})
# The check can fail: a tree with one function of 121 lines (a signature, 119 statements, a brace).
set(long_function "// A function one line over the limit.\nint tooLong(int x) {\n")
foreach(i RANGE 1 119)
    string(APPEND long_function "    x += ${i}; // { a brace in a comment does not count\n")
endforeach()
string(APPEND long_function "}\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/function_length_check/common/frame/src/long.cpp "${long_function}")
add_test(NAME "function length: rejects a function of 121 lines"
         COMMAND ${EXPECT} 1 "long.cpp:2: tooLong is 121 lines, over 120" --
                 ${Python3_EXECUTABLE} ${FUNCTION_LENGTH} ${CMAKE_CURRENT_BINARY_DIR}/function_length_check)

# --- The contract: every stage's shaders agree with common/base/include/t10/contract.hpp. -----------
set(CONTRACT_CHECK ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/contract_check.py
    ${PROJECT_SOURCE_DIR}/common/base/include/t10/contract.hpp)
# tools/bench/shaders: the bench's own versions of the final pass read the same units.
set(shader_dirs ${PROJECT_SOURCE_DIR}/common/shaders ${PROJECT_SOURCE_DIR}/common/optional/shaders
                ${PROJECT_SOURCE_DIR}/tools/bench/shaders)
foreach(stage IN LISTS T10_STAGES)
    list(APPEND shader_dirs ${PROJECT_SOURCE_DIR}/${stage})
endforeach()
add_test(NAME "contract: shaders agree with contract.hpp" COMMAND ${EXPECT} 0 "all agree" -- ${CONTRACT_CHECK} ${shader_dirs})
# The check can fail: Part 3's final shader reading the bloom from unit 18, and extras' with the
# bloom weight at location 4.
file(READ ${PROJECT_SOURCE_DIR}/tutorial10_part3_gaussian/PostProcess.frag shader)
string(REPLACE "binding = 17) uniform sampler2D s2BloomTexture" "binding = 18) uniform sampler2D s2BloomTexture"
       shader "${shader}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/contract_check/unit18/PostProcess.frag "${shader}")
file(READ ${PROJECT_SOURCE_DIR}/extras/PostProcess.frag shader)
string(REPLACE "location = 1) uniform float fBloomStrength" "location = 4) uniform float fBloomStrength" shader "${shader}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/contract_check/location4/PostProcess.frag "${shader}")
add_test(NAME "contract: rejects a shader with another bloom unit"
         COMMAND ${EXPECT} 1 "unit of s2BloomTexture is 18, contract.hpp's kBloomUnit is 17" --
                 ${CONTRACT_CHECK} ${CMAKE_CURRENT_BINARY_DIR}/contract_check/unit18)
add_test(NAME "contract: rejects a shader with another uniform location"
         COMMAND ${EXPECT} 1 "location of fBloomStrength is 4, contract.hpp's kBloomStrengthLocation is 1" --
                 ${CONTRACT_CHECK} ${CMAKE_CURRENT_BINARY_DIR}/contract_check/location4)

# --- The command line (parsed by common/, so one stage is enough). ----------------------------
set(S0 tutorial10_part0_start)
foreach(case
        "--size;1x10;each side must be from 2"
        "--size;big;not WIDTHxHEIGHT"
        "--size;20000x10;each side must be from 2 to 16384"
        "--frames;0;--frames"
        "--frames;abc;--frames"
        "--camera;nowhere;unknown camera"
        "--backend;vulkan;--backend"
        "--output;frame.jpg;must end in .png"
        "--exr;frame.png;must end in .exr"
        "--input;/no/such/file.exr;--input"
        "--shader-dir;/no/such/dir;--shader-dir"
        "--resize-sequence;10x;not WIDTHxHEIGHT"
        "--resize-sequence;64x64,;--resize-sequence 64x64,: size 2 is empty"
        "--resize-sequence;,64x64;size 1 is empty"
        "--resize-sequence;64x64,,32x32;size 2 is empty"
        "--no-such-option;;no-such-option")
    list(GET case 0 option)
    list(GET case 1 value)
    list(GET case 2 message)
    add_test(NAME "cli: rejects ${option} ${value}"
             COMMAND ${EXPECT} 2 "${message}" -- ${BIN}/${S0} --headless ${option} ${value})
endforeach()
add_test(NAME "cli: --headless with --backend window" COMMAND ${EXPECT} 2 "contradicts" --
         ${BIN}/${S0} --headless --backend window)
add_test(NAME "cli: --version" COMMAND ${EXPECT} 0 "${S0} [0-9]" -- ${BIN}/${S0} --version)
# --bench is common/'s: a stage without pass timers reports its frame time.
add_test(NAME "bench: any stage can be benchmarked"
         COMMAND ${EXPECT} 0 "^frame +[0-9.]+ +[0-9.]+ +[0-9.]+" --
                 ${BIN}/${S0} --headless --backend egl --size 160x90 --bench 2 --bench-csv ${OUT}/bench/part0.csv)

# A shader with a syntax error: exit 1, naming the file and quoting the driver's log.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/broken_shaders/PostProcess.frag
     "#version 430 core\nout vec3 v3ColourOut;\nvoid main() { v3ColourOut = undefined_name; }\n")
add_test(NAME "cli: broken shader names the file"
         COMMAND ${EXPECT} 1 "broken_shaders/PostProcess.frag: shader compilation failed" --
         ${BIN}/${S0} ${GOLDEN_ARGS} --shader-dir ${CMAKE_CURRENT_BINARY_DIR}/broken_shaders)
# A GL error during a frame ends the run with exit 1 and the message: a Gauss.frag without the
# subroutine uniform makes Part 3's glUniformSubroutinesuiv call invalid.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/no_subroutine_shaders/Gauss.frag
     "#version 430 core\nlayout(binding = 17) uniform sampler2D s2InputTexture;\nout vec3 v3ColourOut;\n"
     "void main() { v3ColourOut = texelFetch(s2InputTexture, ivec2(gl_FragCoord.xy), 0).rgb; }\n")
add_test(NAME "cli: a GL error fails the run with its message"
         COMMAND ${EXPECT} 1 "error: GL error in frame 0" --
         ${BIN}/tutorial10_part3_gaussian ${GOLDEN_ARGS} --shader-dir ${CMAKE_CURRENT_BINARY_DIR}/no_subroutine_shaders)

# --- Backends, window mode, resizes, HDR output (the part0 stage stands for all). -------------
add_test(NAME "backend: osmesa matches the golden"
         COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/osmesa ${S0} --backend osmesa)
# Every frame's line names the key Ya once a stage has a luminance texture (Part 1 on); Part 0 has none.
add_test(NAME "cli: --verbose prints the key Ya of every frame"
         COMMAND ${EXPECT} 0 "frame 1: [0-9.]+ ms, key Ya 0\\.0[0-9]+" -- ${BIN}/tutorial10_part1_tonemap ${GOLDEN_ARGS} --frames 2 --verbose)
add_test(NAME "cli: --verbose prints no key without a luminance texture"
         COMMAND ${EXPECT} 0 "frame 0: [0-9.]+ ms$" -- ${BIN}/${S0} --backend egl --size 64x36 --frames 1 --verbose)
add_test(NAME "backend: --verbose reports the renderer"
         COMMAND ${EXPECT} 0 "^renderer: " -- ${BIN}/${S0} ${GOLDEN_ARGS} --verbose)
add_test(NAME "resize: headless resizes, including 0x0, then matches the golden"
         COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/resize ${S0} --frames 5
                 --resize-sequence 320x200,0x0,641x361,3x2,640x360)
add_test(NAME "hdr: the EXR holds values above 1.0"
         COMMAND ${CMAKE_COMMAND} -E chdir ${OUT} sh -c
                 "${BIN}/${S0} --headless --size 320x180 --exr ${OUT}/hdr/${S0}.exr && ${BIN}/exrstat ${OUT}/hdr/${S0}.exr --min-max 1.0")
if(XVFB_RUN)
    add_test(NAME "window: renders under Xvfb and matches the golden"
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${GOLDEN_TEST} ${BIN} ${OUT}/window ${S0}
                     --backend window --frames 3)
    add_test(NAME "window: resizes, including 0x0, without GL errors"
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${EXPECT} 0 "wrote" --
                     ${BIN}/${S0} --backend window --size 640x360 --frames 6
                     --resize-sequence 320x200,0x0,801x501,3x2,640x360 --output ${OUT}/window/resized.png)
else()
    add_test(NAME "window: renders under Xvfb" COMMAND ${CMAKE_COMMAND} -E echo "xvfb-run not installed")
    set_tests_properties("window: renders under Xvfb" PROPERTIES DISABLED TRUE)
endif()

# --- Tools. -----------------------------------------------------------------------------------
file(MAKE_DIRECTORY ${OUT}/tga2png)
add_test(NAME "tga2png: converts a committed asset"
         COMMAND ${EXPECT} 0 "" -- ${BIN}/tga2png ${PROJECT_SOURCE_DIR}/common/assets/bricks_depth.tga
                 ${OUT}/tga2png/bricks_depth.png)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bad.tga "not a tga")
add_test(NAME "tga2png: reports a malformed file"
         COMMAND ${EXPECT} 1 "bad.tga: .*truncated" -- ${BIN}/tga2png ${CMAKE_CURRENT_BINARY_DIR}/bad.tga
                 ${OUT}/tga2png/bad.png)
add_test(NAME "tga2png: usage" COMMAND ${EXPECT} 2 "usage" -- ${BIN}/tga2png)
add_test(NAME "assets: make_textures reproduces the committed TGA files"
         COMMAND sh -c "rm -rf '${OUT}/assets' && mkdir -p '${OUT}/assets' && '${BIN}/make_textures' '${OUT}/assets' >/dev/null && for f in '${PROJECT_SOURCE_DIR}'/common/assets/*.tga; do cmp \"$f\" '${OUT}/assets/'\"$(basename \"$f\")\" || exit 1; done && echo identical")
