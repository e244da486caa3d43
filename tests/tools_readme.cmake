# tools/README.md lists every folder of tools/ under its audience, with what runs it (tests/tools_readme.py).
# Included after stage_tests.cmake (EXPECT, Python3).
set(TOOLS_README ${CMAKE_CURRENT_SOURCE_DIR}/tools_readme.py)
add_test(NAME "tools: README lists every folder of tools/ under its audience, with what runs it"
         COMMAND ${EXPECT} 0 "^ok: " -- ${Python3_EXECUTABLE} ${TOOLS_README} ${PROJECT_SOURCE_DIR}/tools
                 ${PROJECT_SOURCE_DIR}/Makefile)

# The check can fail: stand-ins for tools/ (today's README, and a folder holding one file for each tool),
# each with one fault, must be reported with it.
file(GLOB tool_entries LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/tools ${PROJECT_SOURCE_DIR}/tools/*)
set(tool_folders "")
foreach(entry IN LISTS tool_entries)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/tools/${entry})
        list(APPEND tool_folders ${entry})
    endif()
endforeach()
file(READ ${PROJECT_SOURCE_DIR}/tools/README.md tools_readme)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/README.md)

# t10_add_tools_readme_mutant(<name> <regex> <README text> <folder>...)
function(t10_add_tools_readme_mutant name regex readme)
    string(MAKE_C_IDENTIFIER "${name}" folder)
    set(root ${CMAKE_CURRENT_BINARY_DIR}/tools_readme_check/${folder}/tools)
    file(REMOVE_RECURSE ${root})
    file(WRITE ${root}/README.md "${readme}")
    foreach(tool IN LISTS ARGN)
        file(WRITE ${root}/${tool}/stand-in "")
    endforeach()
    add_test(NAME "tools: the README check rejects ${name}"
             COMMAND ${EXPECT} 1 "${regex}" -- ${Python3_EXECUTABLE} ${TOOLS_README} ${root} ${PROJECT_SOURCE_DIR}/Makefile)
endfunction()
t10_add_tools_readme_mutant("a folder the README does not list" "`new_tool/` is not listed"
                            "${tools_readme}" ${tool_folders} new_tool)
list(GET tool_folders 0 gone)
set(others ${tool_folders})
list(REMOVE_ITEM others ${gone})
t10_add_tools_readme_mutant("a listed folder that does not exist" "`${gone}/` is listed, but there is no folder"
                            "${tools_readme}" ${others})
string(REPLACE "`make " "`make no-such-" readme "${tools_readme}")
t10_add_tools_readme_mutant("a make target the Makefile lacks" "`make no-such-[a-z-]+` is no target of"
                            "${readme}" ${tool_folders})
string(REGEX REPLACE "\n## [^\n]*" "\n## Others" readme "${tools_readme}")
t10_add_tools_readme_mutant("a folder under a heading that is no audience" "under 'Others', which is not an audience"
                            "${readme}" ${tool_folders})
