# The sources of t10-grade's checks' core (t10_grade_core: a case's buffers in memory checked against
# the CPU reference, the mistakes named, the cases reconciled, the parts described), relative to
# grader/: the one list grader/CMakeLists.txt builds the library from and the browser build compiles
# into every stage page for its check (grader/page/page.cmake).
set(T10_GRADE_CORE_SOURCES part/part.cpp checks/buffers.cpp checks/findings.cpp checks/table.cpp checks/reconcile.cpp
    diagnosis/catalogue.cpp diagnosis/fits.cpp diagnosis/model.cpp diagnosis/key_model.cpp diagnosis/frame_model.cpp
    diagnosis/bloom_model.cpp)
