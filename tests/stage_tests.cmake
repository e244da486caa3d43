# ctest entries that run the built programs: golden images, rejection proofs, backends, window mode,
# resizes, the command line and the tools. Included from tests/CMakeLists.txt.
set(EXPECT ${CMAKE_CURRENT_SOURCE_DIR}/expect.sh)
set(GOLDEN ${CMAKE_CURRENT_SOURCE_DIR}/golden)
set(GOLDEN_TEST ${GOLDEN}/golden_test.sh)
set(GOLDEN_ARGS --backend egl --size 640x360 --camera default --frames 1)
find_program(XVFB_RUN xvfb-run)

# --- Golden image of every stage, and proof that each golden rejects a wrong image. -----------
set(previous "")
foreach(stage IN LISTS T10_STAGES)
    add_test(NAME "cli: ${stage} --help"
             COMMAND ${EXPECT} 0 "--camera TEXT" -- ${BIN}/${stage} --help)
    get_property(same GLOBAL PROPERTY T10_GOLDEN_OF_${stage})
    if(same)
        # A program that must reproduce another stage's frame exactly (extras/ with its defaults).
        add_test(NAME "golden: ${stage} reproduces ${same}"
                 COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/golden ${stage} --golden ${same})
        continue()
    endif()
    add_test(NAME "golden: ${stage}" COMMAND ${GOLDEN_TEST} ${BIN} ${OUT}/golden ${stage})
    # A visibly altered copy of the stage's own golden must fail.
    add_test(NAME "golden rejects: ${stage} altered"
             COMMAND ${BIN}/imgcompare ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.png ${GOLDEN}/${stage}.tolerance
                     --alter --expect-reject)
    # The previous stage's image must fail this stage's golden.
    if(previous)
        add_test(NAME "golden rejects: ${previous} as ${stage}"
                 COMMAND ${BIN}/imgcompare ${GOLDEN}/${stage}.png ${GOLDEN}/${previous}.png
                         ${GOLDEN}/${stage}.tolerance --expect-reject)
    endif()
    set(previous ${stage})
endforeach()

# --- The stage rule: each stage's diff from the previous one holds exactly its part's steps. ---
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(STAGE_DIFF ${CMAKE_CURRENT_SOURCE_DIR}/stage_diff.py)
set(previous "")
foreach(stage IN LISTS T10_STAGES)
    get_property(steps GLOBAL PROPERTY T10_STEPS_OF_${stage})
    if(previous AND steps)
        add_test(NAME "stage diff: ${previous} -> ${stage} holds only steps ${steps}"
                 COMMAND ${Python3_EXECUTABLE} ${STAGE_DIFF} ${PROJECT_SOURCE_DIR}/${previous}
                         ${PROJECT_SOURCE_DIR}/${stage} ${steps})
    endif()
    set(previous ${stage})
endforeach()
# The check can fail: Part 2 measured against Part 1's step range holds steps 17-25 too many.
add_test(NAME "stage diff: rejects steps of another part"
         COMMAND ${EXPECT} 1 "not part of steps 1-16" -- ${Python3_EXECUTABLE} ${STAGE_DIFF}
                 ${PROJECT_SOURCE_DIR}/tutorial10_part0_start ${PROJECT_SOURCE_DIR}/tutorial10_part2_bloom 1 16)

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
