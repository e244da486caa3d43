# The page's check (grader/page/page_check.cpp, Module.t10Check), included by cmake/T10Web.cmake: the
# checks' core (grader/core_sources.cmake, the list t10-grade's library is built from) and the grader's
# files a page can run as they are (the dump reader, the catalogue's and the rubric's readers, the score,
# the cases' list), compiled into every stage page. The catalogue and the rubric are packaged with the
# page at the paths compiled in here (t10_web_stage); workbench.js is its JavaScript half.
include(${PROJECT_SOURCE_DIR}/grader/core_sources.cmake)
set(grader ${PROJECT_SOURCE_DIR}/grader)
list(TRANSFORM T10_GRADE_CORE_SOURCES PREPEND ${grader}/ OUTPUT_VARIABLE core)
# An object library: its exported entry point stays in every page, though nothing calls it from C++.
add_library(t10_web_check OBJECT ${core} ${grader}/checks/dump_files.cpp ${grader}/diagnosis/catalogue_file.cpp
            ${grader}/scoring/rubric.cpp ${grader}/scoring/score.cpp ${grader}/capture/case_list.cpp
            ${grader}/page/page_check.cpp)
target_include_directories(t10_web_check PRIVATE ${grader})
target_link_libraries(t10_web_check PUBLIC t10_common t10_reference_math PRIVATE t10_flags)
set(T10_WEB_GRADE_ROOT ${T10_WEB_ROOT}/grade)
target_compile_definitions(t10_web_check PRIVATE T10_GRADE_MISTAKES="${T10_WEB_GRADE_ROOT}/mistakes.tsv"
                                                 T10_GRADE_RUBRIC_DEFAULT="${T10_WEB_GRADE_ROOT}/rubric.txt")
# One combined file, as t10-grade's and the core's (grader/CMakeLists.txt): about 25 s of em++ once per
# web build (measured on a loaded machine), shared by every page.
set_target_properties(t10_web_check PROPERTIES UNITY_BUILD_BATCH_SIZE 0)
# The rubric is packaged from a copy without its .txt, which the pages' packaging leaves out (T10Web.cmake).
configure_file(${grader}/scoring/rubric.txt ${PROJECT_BINARY_DIR}/grade/rubric COPYONLY)
set(T10_WEB_GRADE_FILES ${grader}/diagnosis/mistakes.tsv@${T10_WEB_GRADE_ROOT}/mistakes.tsv
                        ${PROJECT_BINARY_DIR}/grade/rubric@${T10_WEB_GRADE_ROOT}/rubric.txt)
