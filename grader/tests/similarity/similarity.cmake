# The similarity tests (issue 51; included from grader/CMakeLists.txt with the grader's tests). Both skip
# (exit 77) where Java or JPlag is not installed (make test installs both: the JRE with the test
# packages, the jars with FLIP). The generated class takes about 15 s of CPU (two JPlag runs of 40
# students, the second without the template to show the check failing); the t10-grade run a few.
set(SIMILARITY_TESTS ${CMAKE_CURRENT_SOURCE_DIR}/tests/similarity)
add_test(NAME "similarity: a generated class of 40: the two planted pairs ranked first and flagged, nobody else; pages escaped"
         COMMAND ${Python3_EXECUTABLE} ${SIMILARITY_TESTS}/similarity_test.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/jplag
                 ${CMAKE_CURRENT_BINARY_DIR}/similarity-test)
add_test(NAME "similarity: t10-grade --similarity lists the pair to review in the class index"
         COMMAND ${GRADE_TESTS}/run_grader.sh ${T10_GRADE_VENV}/bin/flip ${Python3_EXECUTABLE}
                 ${SIMILARITY_TESTS}/grade_similarity_test.py ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/bin/t10-grade
                 ${CMAKE_CURRENT_BINARY_DIR}/similarity-grade-test)
set_tests_properties("similarity: a generated class of 40: the two planted pairs ranked first and flagged, nobody else; pages escaped"
                     "similarity: t10-grade --similarity lists the pair to review in the class index"
                     PROPERTIES SKIP_RETURN_CODE 77 COST 30)
