# Command-line behaviour: exit codes and one-line messages for bad input; files written on
# success are read back through the library (read_output) and counted.
set(cli $<TARGET_FILE:sphereset_cli>)
set(work ${CMAKE_CURRENT_BINARY_DIR}/cli)
file(MAKE_DIRECTORY ${work})
file(WRITE ${work}/open.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
file(WRITE ${work}/nan.off "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
file(WRITE ${work}/garbage.stl "not a mesh at all")
file(WRITE ${work}/lines.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n")
file(WRITE ${work}/flat.obj "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n")
file(WRITE ${work}/empty.obj "")
# The unit cube with one triangle flipped; with an inward cube inside (a cavity); an open sheet.
file(WRITE ${work}/flipped.off "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 4 5\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
file(WRITE ${work}/cavity.off "OFF\n16 24 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n0.25 0.25 0.25\n0.75 0.25 0.25\n0.25 0.75 0.25\n0.75 0.75 0.25\n0.25 0.25 0.75\n0.75 0.25 0.75\n0.25 0.75 0.75\n0.75 0.75 0.75\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n3 8 11 10\n3 8 9 11\n3 12 15 13\n3 12 14 15\n3 8 13 9\n3 8 12 13\n3 10 15 14\n3 10 11 15\n3 8 14 12\n3 8 10 14\n3 9 15 11\n3 9 13 15\n")
file(WRITE ${work}/sheet.off "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
file(WRITE ${work}/bound.txt "# one sphere around the link\n0.0 -0.037 -0.068 0.17\n")
file(WRITE ${work}/bad.txt "0 0 0\n")
set(link ${CMAKE_CURRENT_SOURCE_DIR}/data/fr3_link1_collision.stl)

add_executable(sphereset_cli_read_output ${CMAKE_CURRENT_SOURCE_DIR}/cli/read_output.cpp)
target_link_libraries(sphereset_cli_read_output PRIVATE sphereset::sphereset)
sphereset_warnings(sphereset_cli_read_output)
set(reader $<TARGET_FILE:sphereset_cli_read_output>)

# cli_test(name exit ARGS args... [STDERR regex] [STDOUT regex] [FORBID file]
#          [FILE written [SPHERES n | TRIANGLES n]])
function(cli_test name expect)
  cmake_parse_arguments(A "" "STDERR;STDOUT;FORBID;FILE;SPHERES;TRIANGLES" "ARGS" ${ARGN})
  set(defs -DEXPECT_EXIT=${expect} -DREADER=${reader})
  foreach(key STDERR STDOUT FILE SPHERES TRIANGLES)
    if(A_${key})
      list(APPEND defs "-DEXPECT_${key}=${A_${key}}")
    endif()
  endforeach()
  if(A_FORBID)
    list(APPEND defs "-DFORBID_FILE=${A_FORBID}")
  endif()
  string(REPLACE ";" "|" cmd "${cli};${A_ARGS}")
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" ${defs} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_cli.cmake)
endfunction()

cli_test(check_solid 0 ARGS check ${link}
         STDOUT "solid +closed, oriented 2-manifold.*crossings +0 .*fit will +use it as it is")
cli_test(check_json 0 ARGS check ${link} --json
         STDOUT "\"vertices\":152.*\"triangles\":300|\"triangles\":300.*\"vertices\":152")
cli_test(check_open 5 ARGS check ${work}/open.off --repair off STDOUT "closed +no.*fit will +refuse")
cli_test(check_missing 3 ARGS check ${work}/missing.obj STDERR "missing.obj: no such file")
cli_test(check_garbage 3 ARGS check ${work}/garbage.stl STDERR "garbage.stl: ")
cli_test(check_nan 4 ARGS check ${work}/nan.off STDERR "nan.off: vertex 1 has a NaN")
cli_test(eval_open 5 ARGS eval ${work}/open.off ${work}/bound.txt --repair off
         STDERR "open.off: not a closed solid: 3 boundary edges")
cli_test(eval_bad_spheres 4 ARGS eval ${link} ${work}/bad.txt STDERR "bad.txt:1: expected four numbers")
cli_test(eval_json 0 ARGS eval ${link} ${work}/bound.txt --json --samples 20000 --segments 100
         STDOUT "\"er_sum\":.*\"surface_covered\":true")
cli_test(bad_option 2 ARGS eval ${link} ${work}/bound.txt --samples -5
         STDERR "samples '-5': expected an integer from 0 to 100000000")
cli_test(eval_huge_shadow 2 ARGS eval ${link} ${work}/bound.txt --shadow-resolution 100000
         STDERR "shadow_resolution '100000': expected an integer from 0 to 4096")
cli_test(no_command 2 ARGS)
cli_test(fit_txt 0 ARGS fit ${link} -n 5 -o ${work}/link5.txt --quality fast -q
         FILE ${work}/link5.txt SPHERES 5)
cli_test(fit_bad_extension 2 ARGS fit ${link} -n 5 -o ${work}/link5.xyz -q
         STDERR "link5.xyz: unknown sphere-set extension" FORBID ${work}/link5.xyz)
cli_test(fit_open_mesh 5 ARGS fit ${work}/open.off -n 5 -o ${work}/never1.txt -q --repair off
         STDERR "open.off: not a closed solid" FORBID ${work}/never1.txt)
cli_test(fit_zero_spheres 2 ARGS fit ${link} -n 0 -o ${work}/never2.txt -q FORBID ${work}/never2.txt)
cli_test(fit_too_many 2 ARGS fit ${link} -n 50000 -o ${work}/never3.txt -q --points 1000
         STDERR "50000 spheres" FORBID ${work}/never3.txt)
cli_test(fit_bad_decimation 2 ARGS fit ${link} -n 5 -o ${work}/never11.txt -q --decimation -1
         STDERR "decimation '-1': expected a number from 0 to 16" FORBID ${work}/never11.txt)
cli_test(fit_decimation 0 ARGS fit ${link} -n 5 -o ${work}/link5d.txt --quality fast --decimation 1
         -q --json STDOUT "decimated.:5" FILE ${work}/link5d.txt SPHERES 5)
cli_test(fit_yaml 0 ARGS fit ${link} -n 3 -o ${work}/link3.yaml --name link1 --quality fast -q
         FILE ${work}/link3.yaml SPHERES 3)
cli_test(fit_json 0 ARGS fit ${link} -n 4 -o ${work}/link4.sph --quality fast -q --json
         STDOUT "\"er_sum\":.*\"surface_covered\":true" FILE ${work}/link4.sph SPHERES 4)
cli_test(tree_sph 0 ARGS tree ${link} --branch 3 --depth 2 -o ${work}/link_tree.sph --quality fast -q
         --json STDOUT "\"leaves\":9" FILE ${work}/link_tree.sph SPHERES 9)
cli_test(tree_outside_json 0 ARGS tree ${link} --branch 2 --depth 2 -n 3 --parents outside
         -o ${work}/link_tree.json --quality fast -q --json STDOUT "\"parents\":\"outside\""
         FILE ${work}/link_tree.json SPHERES 3)
cli_test(tree_bad_extension 2 ARGS tree ${link} -o ${work}/never4.yaml -q
         STDERR "never4.yaml: a sphere tree is written as .sph or .json" FORBID ${work}/never4.yaml)
cli_test(tree_too_many_leaves 2 ARGS tree ${link} --branch 2 --depth 2 -n 5 -o ${work}/never5.sph -q
         STDERR "5 leaves do not fit" FORBID ${work}/never5.sph)
cli_test(tree_absurd_depth 2 ARGS tree ${link} --branch 1000 --depth 20 -o ${work}/never6.sph -q
         FORBID ${work}/never6.sph)
cli_test(query_point 0 ARGS query ${work}/bound.txt --point 0,-0.037,-0.068 --point 1,1,1
         STDOUT "inside, signed distance -0.17.*outside")
cli_test(query_bad_point 2 ARGS query ${work}/bound.txt --point 0,0 STDERR "--point takes x,y,z")
cli_test(query_pair_json 0 ARGS query ${work}/bound.txt --other ${work}/bound.txt
         --pose 1,0,0,1,0,0,0 --json STDOUT "\"overlap\":false")
# A Bradshaw tree whose root has two children, only the first with children: the second is a leaf.
file(WRITE ${work}/unbalanced.sph "3 2\n0 0 0 10 0\n-3 0 0 4 0\n5 0 0 2 0\n-4 0 0 1 0\n-2 0 0 1 0\n0 0 0 -1 0\n0 0 0 -1 0\n")
cli_test(query_unbalanced_tree 0 ARGS query ${work}/unbalanced.sph --point 5,0,0
         STDOUT "inside, signed distance -2")
cli_test(export_unbalanced_tree 0 ARGS export ${work}/unbalanced.sph -o ${work}/unbalanced.ply
         --subdivisions 0 FILE ${work}/unbalanced.ply TRIANGLES 60)
cli_test(query_nan_point 2 ARGS query ${work}/bound.txt --point nan,0,0
         STDERR "point .nan 0 0.: coordinates must be finite" STDOUT "^$")
cli_test(query_huge_segment 2 ARGS query ${work}/bound.txt --segment 0,0,0,1e154,1e154,1e154
         STDERR "segment end .* at most 1e.30")
cli_test(query_missing 3 ARGS query ${work}/missing.txt --point 0,0,0 STDERR "missing.txt")
cli_test(render_png 0 ARGS render ${link} ${work}/bound.txt -o ${work}/link.png --size 160x120 --up z
         FILE ${work}/link.png)
cli_test(render_bad_size 2 ARGS render ${link} -o ${work}/never7.png --size 10 STDERR "--size: expected WxH"
         FORBID ${work}/never7.png)
cli_test(render_bad_view 2 ARGS render ${link} -o ${work}/never8.png --views front,back
         STDERR "unknown view 'back'" FORBID ${work}/never8.png)
cli_test(render_not_png 2 ARGS render ${link} -o ${work}/never9.jpg STDERR "must be .png"
         FORBID ${work}/never9.jpg)
# One sphere as an icosahedron subdivided s times: 20·4^s triangles.
cli_test(export_ply 0 ARGS export ${work}/bound.txt -o ${work}/bound_spheres.ply
         FILE ${work}/bound_spheres.ply TRIANGLES 320)
cli_test(export_glb 0 ARGS export ${work}/bound.txt -o ${work}/bound_spheres.glb --subdivisions 1
         FILE ${work}/bound_spheres.glb TRIANGLES 80)
cli_test(export_bad_extension 2 ARGS export ${work}/bound.txt -o ${work}/never10.stl
         STDERR "never10.stl: unknown mesh extension" FORBID ${work}/never10.stl)
# The library's rule for the subdivisions (once clamped there, refused by the command's own check).
cli_test(export_bad_subdivisions 2 ARGS export ${work}/bound.txt -o ${work}/never10b.ply
         --subdivisions 7 STDERR "subdivisions must be from 0 to 6 .got 7." FORBID ${work}/never10b.ply)

# The read-back itself goes through the library's reader: a malformed file fails it.
add_test(NAME cli.read_output_malformed
         COMMAND ${CMAKE_COMMAND} "-DCMD=${reader}|spheres|${work}/bad.txt" -DEXPECT_EXIT=1
                 "-DEXPECT_STDERR=bad.txt:1: expected four numbers" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_cli.cmake)

# The shared pieces of the command line, tested directly: exit code 7 needs a fit that fails its
# own coverage check, which the library does not produce on purpose.
add_executable(sphereset_cli_unit_tests ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_cli_common.cpp)
target_link_libraries(sphereset_cli_unit_tests PRIVATE sphereset_cli_common GTest::gtest_main)
target_compile_definitions(sphereset_cli_unit_tests PRIVATE
  SPHERESET_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data")
sphereset_warnings(sphereset_cli_unit_tests)
gtest_discover_tests(sphereset_cli_unit_tests TEST_PREFIX cli. DISCOVERY_TIMEOUT 60)

# Broken meshes: what check says fit will do, and fits that cover the original triangles.
set(data ${CMAKE_CURRENT_SOURCE_DIR}/data)
cli_test(check_open_box 0 ARGS check ${data}/open_box.off
         STDOUT "closed +no .4 boundary edges.*fit will +repair capped: closed 1 hole")
cli_test(fit_open_box 0 ARGS fit ${data}/open_box.off -n 6 -o ${work}/open_box.txt --quality fast
         --json -q FILE ${work}/open_box.txt SPHERES 6
         STDOUT "\"original_covered\":true.*\"repair\":{[^}]*\"kind\":\"capped\"")
cli_test(fit_open_box_off 5 ARGS fit ${data}/open_box.off -n 6 -o ${work}/never20.txt -q
         --repair off STDERR "open_box.off: not a closed solid: 4 boundary edges"
         FORBID ${work}/never20.txt)
if(SPHERESET_WITH_REPAIR)
  cli_test(check_overlapping 0 ARGS check ${data}/overlapping_cubes.off
           STDOUT "shells +2 .*1 intersecting pairs.*fit will +repair union: united 2 shells")
  cli_test(fit_overlapping 0 ARGS fit ${data}/overlapping_cubes.off -n 8 -o ${work}/cubes.json
           --quality fast --json -q FILE ${work}/cubes.json SPHERES 8
           STDOUT "\"original_covered\":true.*\"kind\":\"union\"")
  cli_test(check_bow_tie 0 ARGS check ${data}/bow_tie.off
           STDOUT "crossings +[1-9][0-9]* intersecting triangle pairs.*fit will +repair wrapped")
  cli_test(fit_bow_tie 0 ARGS fit ${data}/bow_tie.off -n 8 -o ${work}/bow_tie.txt --quality fast
           --json -q FILE ${work}/bow_tie.txt SPHERES 8
           STDOUT "\"kind\":\"wrapped\".*\"wrap_alpha\"")
  cli_test(eval_bow_tie 0 ARGS eval ${data}/bow_tie.off ${work}/bow_tie.txt --samples 2000
           --segments 10 STDOUT "repaired solid's volume.*original covered +yes")
  set_tests_properties(cli.eval_bow_tie PROPERTIES DEPENDS cli.fit_bow_tie)
  cli_test(fit_single_triangle 0 ARGS fit ${work}/open.off -n 3 -o ${work}/tri.txt --quality fast
           -q FILE ${work}/tri.txt SPHERES 3)
  cli_test(fit_keep_cavities 0 ARGS fit ${data}/open_box.off -n 8 -o ${work}/shell.txt
           --keep-cavities --wrap-alpha 0.1 --quality fast --json -q STDOUT "\"kind\":\"wrapped\"")
endif()

# Bad input that no repair can mend: one line naming the file, no output written.
cli_test(fit_lines_only 4 ARGS fit ${work}/lines.obj -n 4 -o ${work}/never21.txt -q
         STDERR "lines.obj: the file contains no triangles" FORBID ${work}/never21.txt)
cli_test(fit_all_degenerate 4 ARGS fit ${work}/flat.obj -n 4 -o ${work}/never22.txt -q
         STDERR "flat.obj: every triangle is degenerate" FORBID ${work}/never22.txt)
cli_test(fit_empty_file 3 ARGS fit ${work}/empty.obj -n 4 -o ${work}/never23.txt -q
         STDERR "empty.obj: the file is empty" FORBID ${work}/never23.txt)
cli_test(fit_nan 4 ARGS fit ${work}/nan.off -n 4 -o ${work}/never24.txt -q
         STDERR "nan.off: vertex 1 has a NaN" FORBID ${work}/never24.txt)
cli_test(fit_bad_alpha 2 ARGS fit ${data}/bow_tie.off -n 4 -o ${work}/never25.txt -q
         --wrap-alpha -1 FORBID ${work}/never25.txt)
cli_test(tree_open_box 0 ARGS tree ${data}/open_box.off --branch 2 --depth 2 -o ${work}/box_tree.json
         --quality fast --json -q STDOUT "\"original_covered\":true.*\"kind\":\"capped\"")
cli_test(check_flipped 0 ARGS check ${work}/flipped.off
         STDOUT "oriented +no.*problem +[0-9]+ inconsistently oriented edges: triangles flipped.*fit will +repair reoriented")
cli_test(fit_flipped 0 ARGS fit ${work}/flipped.off -n 4 -o ${work}/flipped.txt --quality fast
         --json -q FILE ${work}/flipped.txt SPHERES 4 STDOUT "\"kind\":\"reoriented\"")
cli_test(check_cavity 0 ARGS check ${work}/cavity.off
         STDOUT "1 inward-facing, 1 nested.*problem +1 nested shell: 0 dropped .same orientation., 1 cavities filled")
cli_test(fit_cavity_kept 0 ARGS fit ${work}/cavity.off -n 6 -o ${work}/cavity.txt --quality fast
         --keep-cavities --json -q FILE ${work}/cavity.txt SPHERES 6
         STDOUT "\"cavities_kept\":1.*\"kind\":\"none\".*\"volume\":0.875")
# The envelope: openings closed, E_r against the walls too; the robot refuses an envelope size
# with walls.
if(SPHERESET_WITH_REPAIR)
  cli_test(fit_fill_openings 0 ARGS fit ${data}/open_box.off -n 4 -o ${work}/envelope.txt
           --fill-openings 0.5 --quality fast --json -q FILE ${work}/envelope.txt SPHERES 4
           STDOUT "\"er_walls\":[0-9.]+.*\"fill_openings\":0.5.*\"solid\":\"envelope\"")
  # The capped box encloses no hollow: the automatic size keeps the walls.
  cli_test(fit_fill_openings_auto 0 ARGS fit ${data}/open_box.off -n 4 -o ${work}/envelope_auto.txt
           --fill-openings auto --quality fast --json -q
           STDOUT "\"fill_openings\":0.0.*no hollow behind openings narrower than 1.*\"solid\":\"walls\"")
  cli_test(eval_fill_openings 0 ARGS eval ${data}/open_box.off ${work}/envelope.txt
           --fill-openings 0.5 --samples 2000 --segments 10 --json
           STDOUT "\"er_walls\":[0-9.]+.*\"original_covered\":true")
  set_tests_properties(cli.eval_fill_openings PROPERTIES DEPENDS cli.fit_fill_openings)
endif()
cli_test(fit_bad_openings 2 ARGS fit ${data}/open_box.off -n 4 -o ${work}/never_env.txt -q
         --fill-openings -2 STDERR "fill_openings '-2': expected a number from 0 to 1e.30 or auto"
         FORBID ${work}/never_env.txt)
cli_test(robot_walls_with_openings 2 ARGS robot ${data}/robot/three_link.urdf --link-solid walls
         --fill-openings 0.1 -o ${work}/never_walls.yml
         STDERR "every link's solid is its walls: fill_openings 0.1 asks for an envelope" FORBID ${work}/never_walls.yml)
if(SPHERESET_WITH_REPAIR)
  cli_test(fit_sheet 0 ARGS fit ${work}/sheet.off -n 4 -o ${work}/sheet.txt --quality fast --json -q
           FILE ${work}/sheet.txt SPHERES 4 STDOUT "\"original_covered\":true.*\"kind\":\"wrapped\"")
endif()

include(${CMAKE_CURRENT_LIST_DIR}/robot_cli_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/view_cli_tests.cmake)

# Batch: a folder (recursively) or a manifest, one sphere file per mesh, failed items reported,
# up-to-date items skipped on the next run.
file(REMOVE_RECURSE ${work}/batch_in ${work}/batch_ok ${work}/batch_empty)
file(MAKE_DIRECTORY ${work}/batch_in/sub ${work}/batch_ok/sub ${work}/batch_empty)
file(COPY ${link} DESTINATION ${work}/batch_in)
file(COPY ${link} DESTINATION ${work}/batch_ok)
file(COPY ${work}/cavity.off DESTINATION ${work}/batch_in/sub)
file(COPY ${work}/cavity.off DESTINATION ${work}/batch_ok/sub)
file(WRITE ${work}/batch_in/bad.stl "not a mesh at all")
file(WRITE ${work}/batch.csv "# items\nmesh,n,output\n${link},3,robot/link3.txt\ncavity.off,5,\n")
file(WRITE ${work}/batch.jsonl "{\"mesh\": \"cavity.off\", \"n\": 5, \"seed\": 3}\n")
file(WRITE ${work}/batch_bad.csv "mesh,n\ncavity.off,abc\n")
cli_test(batch_failed_item 8 ARGS batch ${work}/batch_in -o ${work}/batch_in_out -n 4 --quality fast
         -q STDERR "batch_in: 1 of 3 items failed .see .*report.jsonl"
         FILE ${work}/batch_in_out/sub/cavity.json SPHERES 4)
cli_test(batch_failed_dry_run 0 ARGS batch ${work}/batch_in -o ${work}/batch_in_out -n 4
         --quality fast --dry-run
         STDOUT "bad.stl -> bad.json n=4 to fit\n.*fr3_link1_collision.stl -> fr3_link1_collision.json n=4 up to date\n.*cavity.off -> sub/cavity.json n=4 up to date")
set_tests_properties(cli.batch_failed_dry_run PROPERTIES DEPENDS cli.batch_failed_item)
# --force: the first run fits both items whatever an earlier, interrupted run left in the folder.
cli_test(batch_first 0 ARGS batch ${work}/batch_ok -o ${work}/batch_ok_out -n 4 --quality fast
         --format txt --force STDERR "2 items: 2 fitted, 0 skipped, 0 failed"
         FILE ${work}/batch_ok_out/fr3_link1_collision.txt SPHERES 4)
cli_test(batch_resumed 0 ARGS batch ${work}/batch_ok -o ${work}/batch_ok_out -n 4 --quality fast
         --format txt STDERR "2 items: 0 fitted, 2 skipped, 0 failed")
set_tests_properties(cli.batch_resumed PROPERTIES DEPENDS cli.batch_first)
cli_test(batch_changed_options 0 ARGS batch ${work}/batch_ok -o ${work}/batch_ok_out -n 4
         --quality fast --format txt --seed 2 STDERR "2 items: 2 fitted, 0 skipped, 0 failed")
set_tests_properties(cli.batch_changed_options PROPERTIES DEPENDS cli.batch_resumed)
cli_test(batch_csv 0 ARGS batch ${work}/batch.csv -o ${work}/batch_csv_out --quality fast -q
         FILE ${work}/batch_csv_out/robot/link3.txt SPHERES 3)
cli_test(batch_jsonl 0 ARGS batch ${work}/batch.jsonl -o ${work}/batch_jsonl_out --quality fast -q
         --format sph FILE ${work}/batch_jsonl_out/cavity.sph SPHERES 5)
# A tolerance no count up to the cap meets: each item fails (exit 8, nothing written), or with
# --best-effort its best count is written and the run ends with exit 10.
cli_test(batch_tolerance_unmet 8 ARGS batch ${work}/batch_ok -o ${work}/batch_unmet_out
         --max-protrusion 0.0000001 --max-spheres 2 --quality fast --format txt -q
         STDERR "2 of 2 items failed" FORBID ${work}/batch_unmet_out/fr3_link1_collision.txt)
cli_test(batch_best_effort 10 ARGS batch ${work}/batch_ok -o ${work}/batch_best_out
         --max-protrusion 0.0000001 --max-spheres 2 --quality fast --format txt --best-effort
         --force -q STDERR "2 of 2 items missed their tolerance .the best count found written"
         FILE ${work}/batch_best_out/fr3_link1_collision.txt)
cli_test(batch_bad_manifest 4 ARGS batch ${work}/batch_bad.csv -o ${work}/never40 -q
         STDERR "batch_bad.csv:2: n 'abc': expected an integer" FORBID ${work}/never40)
cli_test(batch_missing 3 ARGS batch ${work}/missing_folder -o ${work}/never41 -q
         STDERR "missing_folder: no such file or folder" FORBID ${work}/never41)
cli_test(batch_empty 0 ARGS batch ${work}/batch_empty -o ${work}/batch_empty_out
         STDERR "batch_empty: no meshes")
cli_test(batch_bad_format 2 ARGS batch ${work}/batch_ok -o ${work}/never42 --format obj
         FORBID ${work}/never42)
# A cap without a limit would cap nothing: refused by the library's rule before any item.
cli_test(batch_cap_without_tolerance 2 ARGS batch ${work}/batch_ok -o ${work}/never43
         --max-spheres 8 -q STDERR "max_spheres goes with a tolerance" FORBID ${work}/never43)

# Animation: a 1 x 1 x 2 box, rest and two deformed frames with the same vertices (the top
# sheared, then pulled out), a skinned SMD box of two bones whose top bends in a 3-frame clip
# (written here, no external asset), and a tetrahedron (a different vertex count).
file(WRITE ${work}/box_rest.off "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 2\n1 0 2\n0 1 2\n1 1 2\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
file(WRITE ${work}/box_f1.off "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.3 0 2\n1.3 0 2\n0.3 1 2\n1.3 1 2\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
file(WRITE ${work}/box_f2.off "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0 2.6\n1.5 0 2.6\n0.5 1 2.6\n1.5 1 2.6\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
file(WRITE ${work}/tet.off "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
file(WRITE ${work}/box_one.txt "0.5 0.5 1 1.23\n")
file(WRITE ${work}/box.smd "version 1\nnodes\n0 \"root\" -1\n1 \"tip\" 0\nend\nskeleton\ntime 0\n0 0 0 0 0 0 0\n1 0 0 1 0 0 0\ntime 1\n0 0 0 0 0 0 0\n1 0 0 1 0.3 0 0\ntime 2\n0 0 0 0 0 0 0\n1 0 0 1 0.6 0 0\nend\ntriangles\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n0 0 1 0 0 0 1 0 0 1 0 1\n0 1 1 0 0 0 1 0 0 1 0 1\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n0 1 1 0 0 0 1 0 0 1 0 1\n0 1 0 0 0 0 1 0 0 1 0 1\nskin\n1 0 0 2 0 0 1 0 0 1 1 1\n1 1 0 2 0 0 1 0 0 1 1 1\n1 1 1 2 0 0 1 0 0 1 1 1\nskin\n1 0 0 2 0 0 1 0 0 1 1 1\n1 1 1 2 0 0 1 0 0 1 1 1\n1 0 1 2 0 0 1 0 0 1 1 1\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n0 1 0 0 0 0 1 0 0 1 0 1\n1 1 0 2 0 0 1 0 0 1 1 1\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n1 1 0 2 0 0 1 0 0 1 1 1\n1 0 0 2 0 0 1 0 0 1 1 1\nskin\n0 0 1 0 0 0 1 0 0 1 0 1\n1 0 1 2 0 0 1 0 0 1 1 1\n1 1 1 2 0 0 1 0 0 1 1 1\nskin\n0 0 1 0 0 0 1 0 0 1 0 1\n1 1 1 2 0 0 1 0 0 1 1 1\n0 1 1 0 0 0 1 0 0 1 0 1\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n1 0 0 2 0 0 1 0 0 1 1 1\n1 0 1 2 0 0 1 0 0 1 1 1\nskin\n0 0 0 0 0 0 1 0 0 1 0 1\n1 0 1 2 0 0 1 0 0 1 1 1\n0 0 1 0 0 0 1 0 0 1 0 1\nskin\n0 1 0 0 0 0 1 0 0 1 0 1\n0 1 1 0 0 0 1 0 0 1 0 1\n1 1 1 2 0 0 1 0 0 1 1 1\nskin\n0 1 0 0 0 0 1 0 0 1 0 1\n1 1 1 2 0 0 1 0 0 1 1 1\n1 1 0 2 0 0 1 0 0 1 1 1\nend\n")
# The same vertices with two triangles' corners permuted: not the rest mesh's triangles.
file(WRITE ${work}/box_perm.off "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 2\n1 0 2\n0 1 2\n1 1 2\n3 0 3 1\n3 0 2 3\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
cli_test(animate_frame_triangles 4 ARGS animate ${work}/box_rest.off ${work}/box_one.txt
         -o ${work}/never66 --frames ${work}/box_perm.off
         STDERR "box_rest.off: frame 0 ..*box_perm.off.: its triangles differ from the rest mesh's" FORBID ${work}/never66)
cli_test(animate_not_bind_pose 4 ARGS animate ${work}/box_f1.off ${work}/box_one.txt
         -o ${work}/never67 --animation ${work}/box.smd
         STDERR "box_f1.off: the rest mesh is not the skin's bind pose .vertex [0-9]+ differs." FORBID ${work}/never67)
cli_test(animate_frames 0 ARGS animate ${work}/box_rest.off ${work}/box_one.txt -o ${work}/anim
         --frames ${work}/box_f1.off ${work}/box_f2.off --rebound -q
         FILE ${work}/anim/frame_0001.json SPHERES 1)
cli_test(animate_summary 0 ARGS animate ${work}/box_rest.off ${work}/box_one.txt -o ${work}/anim_s
         --frames ${work}/box_rest.off ${work}/box_f2.off --rebound --format txt
         STDERR "frame 2/2.*2 frames, 1 covered with fixed radii .mean value weights."
         FILE ${work}/anim_s/summary.json)
cli_test(animate_txt_frame 0 ARGS animate ${work}/box_rest.off ${work}/box_one.txt -o ${work}/anim_t
         --frames ${work}/box_f1.off --format txt -q FILE ${work}/anim_t/frame_0000.txt SPHERES 1)
cli_test(animate_skinned 0 ARGS animate ${work}/box.smd ${work}/box_one.txt -o ${work}/anim_smd
         --animation ${work}/box.smd --rebound STDERR "3 frames, [0-9] covered with fixed radii .bone weights."
         FILE ${work}/anim_smd/frame_0002.json SPHERES 1)
cli_test(animate_skinned_fps 0 ARGS animate ${work}/box.smd ${work}/box_one.txt -o ${work}/anim_fps
         --animation ${work}/box.smd --fps 50 --weighting mvc -q FILE ${work}/anim_fps/summary.json)
cli_test(animate_vertex_mismatch 4 ARGS animate ${work}/box_rest.off ${work}/box_one.txt
         -o ${work}/never60 --frames ${work}/box_f1.off ${work}/tet.off
         STDERR "tet.off: 4 vertices and 4 faces, the rest mesh's file .*box_rest.off 8 and 12"
         FORBID ${work}/never60)
cli_test(animate_no_animation 4 ARGS animate ${work}/box_rest.off ${work}/box_one.txt
         -o ${work}/never61 --animation ${work}/box_rest.off
         STDERR "box_rest.off: the asset has no animation" FORBID ${work}/never61)
cli_test(animate_unknown_clip 2 ARGS animate ${work}/box.smd ${work}/box_one.txt -o ${work}/never62
         --animation ${work}/box.smd --clip walk STDERR "box.smd: no clip 'walk' .it has one unnamed"
         FORBID ${work}/never62)
cli_test(animate_frames_and_animation 2 ARGS animate ${work}/box_rest.off ${work}/box_one.txt
         -o ${work}/never63 --frames ${work}/box_f1.off --animation ${work}/box.smd
         FORBID ${work}/never63)
cli_test(animate_neither 2 ARGS animate ${work}/box_rest.off ${work}/box_one.txt -o ${work}/never64
         STDERR "give either --frames or --animation" FORBID ${work}/never64)
cli_test(animate_bad_spheres 4 ARGS animate ${work}/box_rest.off ${work}/bad.txt -o ${work}/never65
         --frames ${work}/box_f1.off STDERR "bad.txt:1: expected four numbers" FORBID ${work}/never65)
cli_test(render_frames 0 ARGS render ${work}/box_rest.off --frames ${work}/box_f1.off
         ${work}/box_f2.off --spheres-dir ${work}/anim -o ${work}/anim_shot.png --size 160x120
         FILE ${work}/anim_shot_0001.png)
set_tests_properties(cli.render_frames PROPERTIES DEPENDS cli.animate_frames)
cli_test(render_animation 0 ARGS render ${work}/box.smd --animation ${work}/box.smd
         --spheres-dir ${work}/anim_smd -o ${work}/smd_shot.png --size 160x120
         FILE ${work}/smd_shot_0002.png)
set_tests_properties(cli.render_animation PROPERTIES DEPENDS cli.animate_skinned)
cli_test(render_frames_mismatch 4 ARGS render ${work}/box_rest.off --frames ${work}/tet.off
         -o ${work}/never66.png STDERR "tet.off: frame 0 has 4 vertices" FORBID ${work}/never66_0000.png)

# The wrap's limits (the library's checks before CGAL runs): these used to end in a
# floating-point signal inside GMP or run for minutes.
if(SPHERESET_WITH_REPAIR)
  file(WRITE ${work}/huge_tri.off "OFF\n3 1 0\n1e80 0 0\n2e80 0 0\n1e80 1e80 0\n3 0 1 2\n")
  cli_test(wrap_alpha_huge 2 ARGS fit ${CMAKE_CURRENT_SOURCE_DIR}/data/bow_tie.off -n 4
           -o ${work}/never80.json --wrap-alpha 1e200
           STDERR "sphereset: wrap_alpha '1e200': expected a number from 0 to 1e.30" FORBID ${work}/never80.json)
  cli_test(wrap_alpha_beyond_the_mesh 2 ARGS fit ${CMAKE_CURRENT_SOURCE_DIR}/data/bow_tie.off -n 4
           -o ${work}/never38.json --wrap-alpha 1e6
           STDERR "wrap_alpha 1e.06 is more than 100 times the mesh's diagonal" FORBID ${work}/never38.json)
  cli_test(wrap_offset_huge 2 ARGS eval ${CMAKE_CURRENT_SOURCE_DIR}/data/bow_tie.off ${work}/bound.txt
           --wrap-offset 1e308 STDERR "wrap_offset '1e308': expected a number from 0 to 1e.30")
  cli_test(wrap_huge_coordinates 4 ARGS fit ${work}/huge_tri.off -n 4 -o ${work}/never81.json
           STDERR "coordinates up to 2e.80 cannot be wrapped" FORBID ${work}/never81.json)
  cli_test(wrap_offset_too_many_triangles 2 ARGS check ${work}/open.off --wrap-offset 10
           STDOUT "fit will +refuse it: .*would make about .* triangles .the limit is 1e.06.")
endif()

# fit with a tolerance: the fewest spheres whose certified protrusion is within 12 % of the
# diagonal (a count tried below it did not meet it), the curve on request; a tolerance no
# count up to the cap meets is exit 10 with nothing written, or the best set with
# --best-effort; -n with a tolerance, and bad tolerances, are exit 2.
cli_test(fit_tolerance 0 ARGS fit ${link} --max-protrusion 12% --quality fast --curve
         ${work}/link_curve.csv -o ${work}/link_tol.json --json -q
         FILE ${work}/link_curve.csv
         STDOUT "\"tolerance\":\\{\"curve\":.*\"meets\":false.*\"met\":true")
cli_test(fit_tolerance_not_met 10 ARGS fit ${link} --max-protrusion 0.0000001 --max-spheres 4
         --quality fast -o ${work}/never_tol.json -q
         STDERR "no count up to 4 meets the tolerance .best: n = [0-9]+, protrusion" FORBID ${work}/never_tol.json)
cli_test(fit_tolerance_best_effort 10 ARGS fit ${link} --max-protrusion 0.0000001 --max-spheres 2
         --quality fast --best-effort -o ${work}/best_effort.json -q FILE ${work}/best_effort.json)
cli_test(fit_tolerance_with_n 2 ARGS fit ${link} -n 8 --max-er 0.5 -o ${work}/never_tol2.json
         STDERR "n and a tolerance .max_protrusion, max_er. exclude each other" FORBID ${work}/never_tol2.json)
cli_test(fit_tolerance_zero 2 ARGS fit ${link} --max-protrusion 0 -o ${work}/never_tol5.json
         STDERR "max_protrusion '0': expected a number above 0 and at most" FORBID ${work}/never_tol5.json)
cli_test(fit_tolerance_percent_twice 2 ARGS fit ${link} --max-protrusion 5%% -o ${work}/never_tol6.json
         STDERR "max_protrusion '5%%': expected a number above 0 and at most 1e.30, optionally followed by %"
         FORBID ${work}/never_tol6.json)
cli_test(fit_help_percent 0 ARGS fit --help STDOUT "--max-protrusion FLOAT.%.")
cli_test(fit_tolerance_nan 2 ARGS fit ${link} --max-er nan -o ${work}/never_tol3.json
         STDERR "max_er 'nan': expected a number above 0 and at most 1000000" FORBID ${work}/never_tol3.json)
# curve: every count from 1 to N from one progressive run, as CSV (and JSON on request); counts
# not increasing, not numbers, or with --max-spheres are exit 2, before anything is written.
cli_test(curve 0 ARGS curve ${link} --max-spheres 4 --quality fast -o ${work}/curve.csv --json -q
         FILE ${work}/curve.csv
         STDOUT "\"covered\":true.*\"n\":1,.*\"n\":2,.*\"n\":3,.*\"n\":4,.*\"progressive\":true")
cli_test(curve_counts_order 2 ARGS curve ${link} --counts 4,2 -o ${work}/never_curve2.csv -q
         STDERR "counts: 2 after 4: expected increasing counts" FORBID ${work}/never_curve2.csv)
cli_test(curve_counts_text 2 ARGS curve ${link} --counts 2,x -o ${work}/never_curve3.csv -q
         STDERR "counts '2,x': expected integers separated by commas" FORBID ${work}/never_curve3.csv)
cli_test(curve_n 2 ARGS curve ${link} -n 4 -o ${work}/never_curve4.csv -q
         STDERR "not expected: 4 -n" FORBID ${work}/never_curve4.csv)
cli_test(curve_counts_empty 2 ARGS curve ${link} --counts 2,,4 -o ${work}/never_curve5.csv -q
         STDERR "counts '2,,4': expected integers separated by commas" FORBID ${work}/never_curve5.csv)
cli_test(curve_too_many 2 ARGS curve ${link} --max-spheres 5000 -o ${work}/never_curve6.csv -q
         STDERR "max_spheres 5000: expected an integer from 1 to 1024" FORBID ${work}/never_curve6.csv)
cli_test(fit_curve_without_tolerance 2 ARGS fit ${link} -n 4 --curve ${work}/never_curve.csv
         -o ${work}/never_tol4.json STDERR "--curve goes with a tolerance"
         FORBID ${work}/never_tol4.json)
cli_test(fit_best_effort_without_tolerance 2 ARGS fit ${link} -n 4 --best-effort
         -o ${work}/never_tol8.json STDERR "best_effort goes with a tolerance .max_protrusion, max_er."
         FORBID ${work}/never_tol8.json)
cli_test(fit_cap_without_tolerance 2 ARGS fit ${link} -n 4 --max-spheres 8
         -o ${work}/never_tol7.json STDERR "max_spheres goes with a tolerance .max_protrusion, max_er."
         FORBID ${work}/never_tol7.json)
