# Reliability tests (issue 14): no run exits 0 without every output it was asked for, refused
# inputs cost bounded time and memory, a full disk leaves no broken file, non-finite input pixels
# are clamped in every stage, a window destroyed from outside ends cleanly. Included from
# tests/CMakeLists.txt, which has set BIN, OUT, EXPECT, XVFB_RUN and T10_STAGES.
set(REL ${CMAKE_CURRENT_LIST_DIR})
set(REL_IN ${CMAKE_CURRENT_BINARY_DIR}/reliability/inputs)
set(REL_OUT ${CMAKE_CURRENT_BINARY_DIR}/reliability/out)
set(S0 tutorial10_part0_start)
set(S3 tutorial10_part3_gaussian)

add_executable(make_inputs ${REL}/make_inputs.cpp)
target_link_libraries(make_inputs PRIVATE OpenEXR::OpenEXR t10_flags)
add_executable(check_finite ${REL}/check_finite.cpp)
target_link_libraries(check_finite PRIVATE t10_common t10_flags)
add_library(full_disk_shim MODULE ${REL}/full_disk_shim.c)
target_link_libraries(full_disk_shim PRIVATE ${CMAKE_DL_LIBS})

add_test(NAME "reliability: inputs" COMMAND ${BIN}/make_inputs ${REL_IN})
set_tests_properties("reliability: inputs" PROPERTIES FIXTURES_SETUP reliability_inputs)
# t10_reliability_test(<name> <command...>): a test that needs the generated inputs.
function(t10_reliability_test name)
    add_test(NAME "reliability: ${name}" COMMAND ${ARGN})
    set_tests_properties("reliability: ${name}" PROPERTIES FIXTURES_REQUIRED reliability_inputs)
endfunction()

# --- A side of 1: refused with the rule, and no output claimed. -----------------------------------
foreach(size 1x1 1x50 50x1)
    t10_reliability_test("an input of ${size} is refused"
        ${EXPECT} 1 "one_${size}.exr: the image is ${size}. each side must be at least 2" --
        ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/one_${size}.exr --output ${REL_OUT}/one_${size}.png)
endforeach()
# The same rule in --resize-sequence as in --size; 0x0 stands for a minimised window.
add_test(NAME "reliability: --resize-sequence refuses 1x1 like --size"
         COMMAND ${EXPECT} 2 "size '1x1': each side must be from 2 to 16384" --
                 ${BIN}/${S0} --headless --resize-sequence 320x200,1x1)
add_test(NAME "reliability: --help states the size rule"
         COMMAND ${EXPECT} 0 "each side 2 to 16384.*0x0 stands for a minimised window" --
                 sh -c "${BIN}/${S0} --help | tr -s ' \\n' ' '")
# A run whose last frame is 0x0 cannot write its outputs: exit 1, saying so.
add_test(NAME "reliability: outputs after a last frame of 0x0 fail the run"
         COMMAND ${EXPECT} 1 "outputs asked for were not written: the last frame \\(2\\) was 0x0" --
                 ${BIN}/${S0} --headless --backend egl --frames 3 --resize-sequence 64x64,32x32,0x0
                 --output ${REL_OUT}/last_0x0.png)
# ... and the same sequence without outputs is fine.
add_test(NAME "reliability: a last frame of 0x0 without outputs exits 0"
         COMMAND ${EXPECT} 0 "" -- ${BIN}/${S0} --headless --backend egl --frames 3 --resize-sequence 64x64,32x32,0x0)

# --- Messages. ------------------------------------------------------------------------------------
foreach(option --size --output --exr --dump --resize-sequence)
    add_test(NAME "reliability: ${option} \"\" is refused"
             COMMAND ${EXPECT} 2 "${option}" -- ${BIN}/${S0} --headless ${option} "")
endforeach()
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/reliability/a_file "not a folder")
add_test(NAME "reliability: a --dump folder that cannot be made names the option and the reason"
         COMMAND ${EXPECT} 1 "error: --dump .*a_file/sub: cannot create folder .*: Not a directory" --
                 ${BIN}/${S0} --headless --backend egl --size 64x64 --dump ${CMAKE_CURRENT_BINARY_DIR}/reliability/a_file/sub)
# Root reads any file, so the unreadable shader is /proc/self/mem: a regular file whose first page
# cannot be read (EIO).
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/reliability/unreadable_shader)
file(CREATE_LINK /proc/self/mem ${CMAKE_CURRENT_BINARY_DIR}/reliability/unreadable_shader/PostProcess.frag SYMBOLIC)
add_test(NAME "reliability: an unreadable shader says why"
         COMMAND ${EXPECT} 1 "PostProcess.frag: cannot read file: Input/output error" --
                 ${BIN}/${S0} --headless --backend egl --size 64x64
                 --shader-dir ${CMAKE_CURRENT_BINARY_DIR}/reliability/unreadable_shader)

# --- Inputs that would render wrongly without a word. ---------------------------------------------
foreach(kind z_only alpha_only)
    t10_reliability_test("an EXR with no colour channel (${kind}) is refused"
        ${EXPECT} 1 "${kind}.exr: the EXR has no colour \\(R, G, B\\) or luminance \\(Y\\) channel \\(its channels: (Z|A)\\)" --
        ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/${kind}.exr --output ${REL_OUT}/${kind}.png)
endforeach()
t10_reliability_test("a luminance-only EXR renders"
    ${EXPECT} 0 "wrote" -- ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/y_only.exr --output ${REL_OUT}/y_only.png)
# --input alone loads no room (input_alone_test.sh), yet --camera and --scene are still checked
# against the room when they are given with it.
t10_reliability_test("--input alone reads no scene"
    ${REL}/input_alone_test.sh ${BIN}/${S3} ${REL_IN}/y_only.exr ${REL_OUT}/y_only_alone.png)
t10_reliability_test("--input with an unknown --camera is refused as without it"
    ${EXPECT} 2 "--camera nowhere: unknown camera" --
    ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/y_only.exr --camera nowhere --output ${REL_OUT}/y_only_camera.png)
t10_reliability_test("--input with --camera reads the scene"
    ${EXPECT} 0 "scene: .*triangles" --
    ${BIN}/${S3} --headless --backend egl --verbose --input ${REL_IN}/y_only.exr --camera lights --output ${REL_OUT}/y_only_lights.png)
# +inf, -inf and NaN in three pixels (inf_nan.exr): every stage warns once over three frames, every
# dumped texture level is finite, and the +inf pixel (1, 1) saturates instead of turning black.
foreach(stage IN LISTS T10_STAGES)
    t10_reliability_test("${stage}: non-finite input pixels are clamped with one warning"
        ${REL}/nonfinite_test.sh ${BIN} ${stage} ${REL_IN}/inf_nan.exr ${REL_OUT}/nonfinite_${stage})
endforeach()
# The check fails when the pixels are passed on as they are (the tone map's inf / inf is black).
t10_reliability_test("the non-finite check rejects unclamped input"
    ${EXPECT} 1 "not finite|not saturated" --
    ${REL}/nonfinite_test.sh ${BIN} tutorial10_part1_tonemap ${REL_IN}/inf_nan.exr ${REL_OUT}/nonfinite_kept --keep-non-finite)

# --- Bounded time and memory for refused oversized inputs. ------------------------------------------
# Peak resident memory bounds: a headless stage with llvmpipe peaks near 75 MiB on its own (measured:
# 73 MiB refusing huge.exr); 256 MiB allows for other drivers and sanitizer builds while a read of the
# 20000 x 20000 file (3.2 GB of half RGBA, 9.5 GB before the fix) or the 1 GiB the TGA bomb declares
# cannot fit. Time: a second for the EXR, as the issue asks (sanitizer builds: five, they run 2-5x
# slower); the TGA bomb decodes 2 million packets before it is found truncated: five seconds.
set(REL_TGA_SECONDS 5)
if(T10_SANITIZE)
    set(REL_SECONDS 5)
    set(REL_MIB 768)
else()
    set(REL_SECONDS 1)
    set(REL_MIB 256)
endif()
t10_reliability_test("a 20000x20000 EXR is refused in bounded time and memory"
    ${REL}/measure.sh 1 "huge.exr: the image is 20000x20000, larger than [0-9]+ on a side \\(GL_MAX" ${REL_SECONDS} ${REL_MIB} --
    ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/huge.exr --output ${REL_OUT}/huge.png)
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME "reliability: the RLE TGA bomb is refused in bounded memory"
         COMMAND sh -c "${Python3_EXECUTABLE} ${REL}/make_tga_bomb.py ${CMAKE_CURRENT_BINARY_DIR}/reliability/bomb.tga && ${REL}/measure.sh 1 'bomb.tga: RLE data truncated' ${REL_TGA_SECONDS} ${REL_MIB} -- ${BIN}/tga2png ${CMAKE_CURRENT_BINARY_DIR}/reliability/bomb.tga ${REL_OUT}/bomb.png")
# The bounds can fail: the same measurement with a limit below the stage's own footprint must.
t10_reliability_test("the memory bound rejects a run above it"
    ${EXPECT} 1 "FAIL: peak RSS" -- ${REL}/measure.sh 1 "huge.exr" ${REL_SECONDS} 8 --
    ${BIN}/${S3} --headless --backend egl --input ${REL_IN}/huge.exr)

# --- A full disk: exit 1 with the reason, the old file intact, no partial file. ---------------------
add_test(NAME "reliability: a full disk fails PNG, EXR and PFM writes cleanly"
         COMMAND ${REL}/full_disk_test.sh $<TARGET_FILE:full_disk_shim> ${BIN}/${S0} ${REL_OUT}/full_disk)

# --- A window destroyed by another X client ends the run cleanly. -----------------------------------
if(XVFB_RUN)
    find_package(X11 REQUIRED)
    add_executable(x_destroy_window ${REL}/x_destroy_window.c)
    target_link_libraries(x_destroy_window PRIVATE X11::X11)
    add_test(NAME "reliability: a window destroyed from outside exits cleanly"
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${REL}/window_closed_test.sh
                     $<TARGET_FILE:x_destroy_window> ${BIN}/${S0} ${S0} ${REL_OUT}/window)
endif()
