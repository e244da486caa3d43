# golden_test.sh for systems without bash (Windows): renders one stage at the golden settings and
# compares it with its golden. Run by ctest as
#   cmake [-DEMULATOR=wine] -DSTAGE=<exe> -DIMGCOMPARE=<exe> -DGOLDEN=<golden without .png> -DOUT=<out
#         without .png> "-DARGS=<stage arguments>" -P golden_test.cmake
# EMULATOR runs a cross-compiled program (Wine); empty on Windows itself.
if(NOT EXISTS ${STAGE})
    get_filename_component(name ${STAGE} NAME_WE)
    message(FATAL_ERROR "${STAGE} is not built: cmake --build <build folder> --target ${name}")
endif()
get_filename_component(out_dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${out_dir})
execute_process(COMMAND ${EMULATOR} ${STAGE} ${ARGS} --output ${OUT}.png RESULT_VARIABLE rendered)
if(NOT rendered EQUAL 0)
    message(FATAL_ERROR "${STAGE} failed (${rendered})")
endif()
execute_process(COMMAND ${EMULATOR} ${IMGCOMPARE} ${GOLDEN}.png ${OUT}.png ${GOLDEN}.tolerance --diff-prefix ${OUT}
                RESULT_VARIABLE compared)
if(NOT compared EQUAL 0)
    message(FATAL_ERROR "${OUT}.png differs from ${GOLDEN}.png beyond ${GOLDEN}.tolerance (imgcompare: ${compared})")
endif()
