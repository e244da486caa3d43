# The glTF loader (--scene): fixtures written by tools/make_gltf_fixtures, the loader's own checks
# (no GL), the fixtures rendered by Part 3 and measured, malformed files through a stage binary
# (exit 1, the message, no output file), and the committed built-in scene against its tool.
# Included from tests/CMakeLists.txt.
set(GLTF_FIXTURES ${CMAKE_CURRENT_BINARY_DIR}/gltf/fixtures)
set(GLTF_RENDERS ${CMAKE_CURRENT_BINARY_DIR}/gltf/renders)
set(GLTF_STAGE tutorial10_part3_gaussian)

add_test(NAME "gltf: write the fixtures" COMMAND ${BIN}/make_gltf_fixtures ${GLTF_FIXTURES})
set_tests_properties("gltf: write the fixtures" PROPERTIES FIXTURES_SETUP gltf_fixtures)

add_executable(t10_gltf_tests gltf/test_gltf_loader.cpp)
target_link_libraries(t10_gltf_tests PRIVATE t10_common t10_flags t10_catch)
target_compile_definitions(t10_gltf_tests PRIVATE T10_TEST_FIXTURE_DIR="${CMAKE_CURRENT_SOURCE_DIR}/fixtures")
catch_discover_tests(t10_gltf_tests TEST_PREFIX "gltf loader: "
                     PROPERTIES FIXTURES_REQUIRED gltf_fixtures ENVIRONMENT T10_GLTF_FIXTURES=${GLTF_FIXTURES})

# Renders: <fixture><form>_<camera>.exr for the three forms of each fixture, the 30 of them as runs of
# one process (the stage's --then; each run loads its own scene): 0.9 CPU s instead of 3.1 for a
# process each, the same EXR files (cmp). A run that fails ends the process with its exit code, and
# "gltf measured" reads every file.
set(gltf_runs "")
foreach(spec "emissive_cubes;front" "lights;top" "cameras;left" "cameras;high" "cameras;framing" "geometry;front"
             "textures;front" "materials;front" "warnings;front" "unit_cube;framing")
    list(GET spec 0 name)
    list(GET spec 1 camera)
    foreach(form "" "_embedded" "_glb")
        if(form STREQUAL "_glb")
            set(file ${GLTF_FIXTURES}/${name}.glb)
        else()
            set(file ${GLTF_FIXTURES}/${name}${form}.gltf)
        endif()
        if(gltf_runs)
            list(APPEND gltf_runs --then)
        endif()
        set(last ${GLTF_RENDERS}/${name}${form}_${camera}.exr)
        list(APPEND gltf_runs --headless --backend egl --size 320x180 --frames 1 --scene ${file} --camera ${camera} --exr ${last})
    endforeach()
endforeach()
add_test(NAME "gltf render: every fixture in its three forms (one process)"
         COMMAND ${EXPECT} 0 "^wrote ${last}" -- ${BIN}/${GLTF_STAGE} ${gltf_runs})
set_tests_properties("gltf render: every fixture in its three forms (one process)"
                     PROPERTIES FIXTURES_SETUP gltf_renders FIXTURES_REQUIRED gltf_fixtures)
add_executable(t10_gltf_render_tests gltf/test_gltf_render.cpp)
target_link_libraries(t10_gltf_render_tests PRIVATE t10_common t10_flags t10_catch)
catch_discover_tests(t10_gltf_render_tests TEST_PREFIX "gltf measured: "
                     PROPERTIES FIXTURES_REQUIRED gltf_renders
                     ENVIRONMENT T10_GLTF_DIR=${CMAKE_CURRENT_BINARY_DIR}/gltf)

# Warnings reach the user: one line each on stderr, and the frame is still written.
add_test(NAME "gltf: warnings are printed and the run succeeds"
         COMMAND ${EXPECT} 0 "warning: .*warnings.glb: points are not drawn" --
                 ${BIN}/${GLTF_STAGE} --backend egl --size 64x64 --frames 1 --scene ${GLTF_FIXTURES}/warnings.glb
                 --output ${GLTF_RENDERS}/warnings_cli.png)
set_tests_properties("gltf: warnings are printed and the run succeeds" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)
add_test(NAME "gltf: -v prints the load time and the triangle count"
         COMMAND ${EXPECT} 0 "scene: .*geometry.glb: 18 triangles.*loaded in [0-9.]+ ms" --
                 ${BIN}/${GLTF_STAGE} --backend egl --size 64x64 --frames 1 -v --scene ${GLTF_FIXTURES}/geometry.glb)
set_tests_properties("gltf: -v prints the load time and the triangle count" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)

# The black-background warning: once, with the key, on a unit cube on nothing (62% of the frame is
# black); never on the built-in room from any of its cameras (at most a few % black).
add_test(NAME "gltf: a model on a black background warns about the key once"
         COMMAND ${EXPECT} 0 "^warning: [0-9]+% of the frame is black \\(the background\\), which pulls the key down to Ya = [0-9.e+-]+ \\(the rest of the frame alone: 0\\.[0-9]+\\)" --
                 ${BIN}/${GLTF_STAGE} --backend egl --size 320x180 --frames 3 --scene ${GLTF_FIXTURES}/unit_cube.glb)
set_tests_properties("gltf: a model on a black background warns about the key once" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)
add_test(NAME "gltf: the warning comes once in three frames"
         COMMAND sh -c "n=$(${BIN}/${GLTF_STAGE} --backend egl --size 320x180 --frames 3 --scene ${GLTF_FIXTURES}/unit_cube.glb 2>&1 | grep -c 'of the frame is black'); echo \"$n warning(s)\"; [ \"$n\" = 1 ]")
set_tests_properties("gltf: the warning comes once in three frames" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)
foreach(camera default floor lights crates dark)
    add_test(NAME "gltf: the built-in room does not warn about a black background (${camera})"
             COMMAND sh -c "out=$(${BIN}/${GLTF_STAGE} --backend egl --size 320x180 --frames 1 --camera ${camera} 2>&1) || { echo \"$out\"; exit 1; }; echo \"$out\"; case \"$out\" in *'of the frame is black'*) echo FAIL: warned; exit 1;; esac")
endforeach()

# Bad input through the program: exit 1, the file and the fault, and no output file.
set(GLTF_REFUSED ${CMAKE_CURRENT_SOURCE_DIR}/gltf/expect_refused.sh)
foreach(case
        "bad_json.gltf;bad_json.gltf: .*parse error"
        "bad_header.glb;bad_header.glb: Invalid glTF binary"
        "bad_missing_buffer.gltf;File not found : no_such_file.bin"
        "bad_short_buffer.gltf;bad_short_buffer.gltf: File size mismatch"
        "bad_missing_image.gltf;image 0 \\(no_such_image.png\\) is missing"
        "bad_truncated_image.gltf;truncated.png\\): cannot decode"
        "bad_accessor_range.gltf;reads past the end of buffer view 0"
        "bad_view_range.gltf;lies outside buffer 0"
        "bad_index.gltf;index 7 \\(element 2\\) is beyond the vertex count 3"
        "bad_nan.gltf;POSITION 2 is not finite"
        "bad_cycle.gltf;node 1 has two parents"
        "bad_cycle_root.gltf;which is not a root"
        "bad_cycle_sceneless.gltf;node 1 is part of a cycle"
        "bad_required_draco.gltf;requires the extension KHR_draco_mesh_compression"
        "bad_wrong_type.gltf;bad_wrong_type.gltf: accessors\\[0\\].count: expected an integer >= 1"
        "schema_normal_scale_string.gltf;materials\\[0\\].normalTexture.scale: expected a number, got a string"
        "schema_mesh_name_number.gltf;meshes\\[0\\].name: expected a string, got a number 1"
        "schema_pbr_not_object.gltf;materials\\[0\\].pbrMetallicRoughness: expected an object"
        "schema_texture_index_negative.gltf;materials\\[0\\].normalTexture.index: expected an integer >= 0, got -1"
        "schema_primitives_object.gltf;meshes\\[0\\].primitives: expected an array, got an object"
        "schema_scene_name_number.gltf;scenes\\[0\\].name: expected a string, got a number 1"
        "nothing_points.gltf;nothing to draw: the scene's only primitive is points or lines")
    list(GET case 0 file)
    list(GET case 1 message)
    add_test(NAME "gltf refuses: ${file}"
             COMMAND ${GLTF_REFUSED} ${BIN}/${GLTF_STAGE} ${GLTF_FIXTURES}/${file} "${message}"
                     ${GLTF_RENDERS}/refused/${file}.png)
    set_tests_properties("gltf refuses: ${file}" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)
endforeach()
# The refusal check can fail: the good triangle renders, so expect_refused.sh must reject it.
add_test(NAME "gltf refuses: the check rejects a good file"
         COMMAND ${EXPECT} 1 "FAIL: exit code 0" -- ${GLTF_REFUSED} ${BIN}/${GLTF_STAGE}
                 ${GLTF_FIXTURES}/good_triangle.gltf "." ${GLTF_RENDERS}/refused/good_triangle.png)
set_tests_properties("gltf refuses: the check rejects a good file" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)

# The command line: the file name's extension, and a camera the scene lacks.
add_test(NAME "cli: rejects --scene with another extension"
         COMMAND ${EXPECT} 2 "must end in .gltf or .glb" -- ${BIN}/${GLTF_STAGE} --headless --scene model.obj)
add_test(NAME "cli: --camera names a camera of the --scene file"
         COMMAND ${EXPECT} 2 "--camera front: unknown camera \\(.*lights.glb has top, framing\\)" --
                 ${BIN}/${GLTF_STAGE} --backend egl --size 64x64 --frames 1 --scene ${GLTF_FIXTURES}/lights.glb
                 --camera front)
set_tests_properties("cli: --camera names a camera of the --scene file" PROPERTIES FIXTURES_REQUIRED gltf_fixtures)

# The committed built-in scene is exactly what tools/make_scene writes.
add_test(NAME "gltf: common/assets/scene.gltf is what make_scene writes"
         COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_CURRENT_BINARY_DIR} sh -c
                 "mkdir -p gltf/scene && ${BIN}/make_scene gltf/scene/scene.gltf >/dev/null && cmp gltf/scene/scene.gltf ${PROJECT_SOURCE_DIR}/common/assets/scene.gltf && cmp gltf/scene/scene.bin ${PROJECT_SOURCE_DIR}/common/assets/scene.bin")

# The example model the site renders is what the tool writes.
add_test(NAME "gltf: site/assets/models/bloom_example.glb is what make_gltf_fixtures --example writes"
         COMMAND ${CMAKE_COMMAND} -E chdir ${CMAKE_CURRENT_BINARY_DIR} sh -c
                 "${BIN}/make_gltf_fixtures --example gltf/example/bloom_example.glb && cmp gltf/example/bloom_example.glb ${PROJECT_SOURCE_DIR}/site/assets/models/bloom_example.glb")

# The measured checks can fail: each mutant is Scene.frag with one line changed, rendered through
# --shader-dir, and the named check must then fail.
# t10_add_gltf_mutant(<name> <from> <to> <fixture> <camera> <test tag> <failing check regex>)
function(t10_add_gltf_mutant name from to fixture camera testcase check)
    file(READ ${PROJECT_SOURCE_DIR}/common/shaders/Scene.frag source)
    string(FIND "${source}" "${from}" found)
    if(found EQUAL -1)
        message(FATAL_ERROR "gltf mutant ${name}: '${from}' not found in common/shaders/Scene.frag")
    endif()
    string(REPLACE "${from}" "${to}" mutated "${source}")
    set(dir ${CMAKE_CURRENT_BINARY_DIR}/gltf/mutants/${name})
    file(WRITE ${dir}/shaders/Scene.frag "${mutated}")
    file(CREATE_LINK ${GLTF_FIXTURES} ${dir}/fixtures SYMBOLIC)
    foreach(form "" "_embedded" "_glb")
        if(form STREQUAL "_glb")
            set(file ${GLTF_FIXTURES}/${fixture}.glb)
        else()
            set(file ${GLTF_FIXTURES}/${fixture}${form}.gltf)
        endif()
        add_test(NAME "gltf mutant: ${name}${form}"
                 COMMAND ${BIN}/${GLTF_STAGE} --backend egl --size 320x180 --frames 1 --scene ${file} --camera ${camera}
                         --shader-dir ${dir}/shaders --exr ${dir}/renders/${fixture}${form}_${camera}.exr)
        set_tests_properties("gltf mutant: ${name}${form}" PROPERTIES FIXTURES_SETUP gltf_mutants
                             FIXTURES_REQUIRED gltf_fixtures)
    endforeach()
    add_test(NAME "gltf measured rejects: ${name}"
             COMMAND ${EXPECT} nonzero "${check}" -- ${CMAKE_COMMAND} -E env T10_GLTF_DIR=${dir}
                     ${BIN}/t10_gltf_render_tests "${testcase}")
    set_tests_properties("gltf measured rejects: ${name}" PROPERTIES FIXTURES_REQUIRED gltf_mutants)
endfunction()

t10_add_gltf_mutant(emission_clamped_to_1
    "v3Result += v3Emissive *" "v3Result += min(v3Emissive, vec3(1.0f)) *" emissive_cubes front
    "[emissive]" "CHECK\\( b.r == Approx\\(4.0f\\)")
t10_add_gltf_mutant(spot_cone_ignored
    "v3Radiance *= fCone * fCone;" "v3Radiance *= 1.0f;" lights top
    "[spot]" "CHECK\\( outside.g < 0.1f \\* inside.g \\)")
t10_add_gltf_mutant(emissive_map_upside_down
    "v3Emissive * textureGrad(s2EmissiveMap, v2TexCoord," "v3Emissive * textureGrad(s2EmissiveMap, vec2(v2TexCoord.x, 1.0f - v2TexCoord.y),"
    textures front "[textures]" "CHECK\\( top.g < 0.1f \\)")
t10_add_gltf_mutant(light_half_a_metre_off
    "vec3 v3ToLight = v4LightPos[i].xyz - v3Position;"
    "vec3 v3ToLight = v4LightPos[i].xyz + vec3(0.5f, 0.0f, 0.0f) - v3Position;" lights top
    "[point]" "CHECK\\( glm::distance\\(best, foot\\) <= 3.0f \\)")
t10_add_gltf_mutant(double_sided_ignored
    "if (!gl_FrontFacing) {" "if (!gl_FrontFacing) { discard; }\n    if (false) {" materials front
    "[materials]" "CHECK\\( twoSided.g == Approx\\(2.0f\\)")
