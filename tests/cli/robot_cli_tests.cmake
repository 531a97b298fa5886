# Command-line behaviour of the robot commands (included by cli_tests.cmake, whose cli_test,
# `cli`, `work` and `data` it uses): robot, eval and render of a URDF, the posed-robot query.
# Robots: every link of a URDF, counts from a budget or per link, outputs in the link frames.
set(robot ${CMAKE_CURRENT_SOURCE_DIR}/data/robot)
cli_test(robot_budget 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot} --budget 12
         --quality fast -o ${work}/three.yml --json -q FILE ${work}/three.yml
         STDOUT "\"link\":\"base_link\".*\"covered\":true.*\"link\":\"link1\".*\"link\":\"link2\".*\"link\":\"tool\"")
# Progress in a log: the stages in order, the curves and the samples to their totals (the
# budget's curves of the 3 fitted links, their fits, the sampled configurations).
cli_test(robot_progress 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot} --budget 12
         --quality fast --collision-samples 600 -o ${work}/three_progress.json
         STDERR "robot: link curves 3/3, link [a-z0-9_]+ .*robot: link fits [0-9]+/[0-9]+, link .*robot: self-collision 600/600 ")
# Protrusion limits: each link's fewest spheres within its limit (JSON per link), a limit no
# count meets under a budget (exit 10, nothing written; --best-effort writes and still exits 10).
cli_test(robot_max_protrusion 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --max-protrusion 0.05 --link-max-protrusion link2=0.06 --quality fast
         -o ${work}/three_tol.json --json -q FILE ${work}/three_tol.json
         STDOUT "\"protrusion_limit\":0.06.*\"tolerance\":true,\"tolerance_met\":true")
# A percentage is of each link's own diagonal: the JSON's limits are lengths, each link's own.
cli_test(robot_max_protrusion_percent 0 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --max-protrusion 30% --link-max-protrusion link2=0.06 --quality fast
         -o ${work}/three_tol_percent.json --json -q FILE ${work}/three_tol_percent.json
         STDOUT "\"protrusion_limit\":0\\.[0-9]+.*\"protrusion_limit\":0.06.*\"tolerance_met\":true")
cli_test(robot_max_protrusion_not_met 10 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --max-protrusion 0.000000001 --budget 6 --quality fast -o ${work}/never_tol.yml -q
         STDERR "three_link.urdf: the protrusion limit is not met .base_link [0-9.e-]+ > 1e-09 with [0-9]+ spheres.*; nothing written"
         FORBID ${work}/never_tol.yml)
cli_test(robot_max_protrusion_best_effort 10 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --max-protrusion 0.000000001 --budget 6 --quality fast --best-effort
         -o ${work}/three_best_effort.yml -q FILE ${work}/three_best_effort.yml)
cli_test(robot_best_effort_without_limit 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --budget 6 --quality fast --best-effort -o ${work}/never_robot_best.yml -q
         STDERR "best_effort goes with a tolerance .max_protrusion, link_max_protrusion.: alone it"
         FORBID ${work}/never_robot_best.yml)
cli_test(robot_link_max_protrusion_zero 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --link-max-protrusion link2=0 -o ${work}/never_tol2.yml -q
         STDERR "link_max_protrusion 'link2=0': expected LINK=VALUE, VALUE a number above 0 and"
         FORBID ${work}/never_tol2.yml)
cli_test(robot_link_counts 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-spheres base_link=2 --link-spheres link1=0 --link-spheres link2=3 --quality fast
         -o ${work}/three.json -q FILE ${work}/three.json)
cli_test(robot_unknown_link 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-spheres elbow=2 -o ${work}/never30.yml -q
         STDERR "three_link.urdf: link_spheres names 'elbow', not a link of three_link"
         FORBID ${work}/never30.yml)
cli_test(robot_missing_package 3 ARGS robot ${robot}/three_link.urdf -o ${work}/never31.yml -q
         STDERR "link 'link2': mesh 'package://three_link_description/meshes/link.stl' not found"
         FORBID ${work}/never31.yml)
cli_test(robot_small_budget 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --budget 2 -o ${work}/never32.yml -q STDERR "budget of" FORBID ${work}/never32.yml)
cli_test(robot_bad_extension 2 ARGS robot ${robot}/three_link.urdf -o ${work}/never33.txt -q
         STDERR "robot output is .yml/.yaml .cuRobo., .lula.yml/.lula.yaml .Lula., .srdf, .urdf, .xml .MJCF., .json or .html"
         FORBID ${work}/never33.txt)
cli_test(robot_yaml_ignore 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --budget 12 --quality fast --joint-positions joint1=0.5,joint2=-0.3 -o ${work}/three_ignore.yml -q
         FILE ${work}/three_ignore.yml)
cli_test(robot_urdf 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot} --budget 12
         --quality fast -o ${work}/three_spheres.urdf -q FILE ${work}/three_spheres.urdf)
cli_test(robot_bad_joint 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --joint-positions joint9=1 -o ${work}/never34.yml -q
         STDERR "--joint-positions: no joint 'joint9' in robot" FORBID ${work}/never34.yml)
cli_test(robot_clamped_joint 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --budget 12 --quality fast --joint-positions joint1=100 -o ${work}/three_clamped.yml -q
         STDERR "warning: joint 'joint1': 100 is beyond its upper limit 1.5, clamped"
         FILE ${work}/three_clamped.yml)
file(MAKE_DIRECTORY ${work}/folder.txt)
# An output that is an input is refused before any work (robot X.urdf -o X.urdf used to replace
# the robot with its spheres); so is an output whose folder cannot take it.
file(COPY_FILE ${robot}/three_link.urdf ${work}/self.urdf)
file(CREATE_LINK ${work}/self.urdf ${work}/self_link.urdf SYMBOLIC)
cli_test(robot_output_is_input 2 ARGS robot ${work}/self.urdf --package-path ${robot}
         -o ${work}/self.urdf -q STDERR "self.urdf: is the input")
cli_test(robot_output_is_input_through_link 2 ARGS robot ${work}/self.urdf --package-path
         ${robot} -o ${work}/self_link.urdf -q STDERR "self_link.urdf: is the input")
add_test(NAME cli.robot_input_unchanged
         COMMAND ${CMAKE_COMMAND} -E compare_files ${robot}/three_link.urdf ${work}/self.urdf)
set_tests_properties(cli.robot_input_unchanged PROPERTIES
                     DEPENDS "cli.robot_output_is_input;cli.robot_output_is_input_through_link")
cli_test(fit_output_is_input 2 ARGS fit ${work}/bound.txt -n 2 -o ${work}/bound.txt -q
         STDERR "bound.txt: is the input")
cli_test(fit_output_folder_missing 6 ARGS fit ${link} -n 2 -o ${work}/no/such/folder/x.json -q
         STDERR "x.json: the folder .* does not exist")
cli_test(fit_output_is_a_folder 2 ARGS fit ${link} -n 2 -o ${work}/folder.txt -q
         STDERR "folder.txt: is a folder")
cli_test(export_output_is_input 2 ARGS export ${work}/unbalanced.sph -o ${work}/unbalanced.sph
         STDERR "is the input")
cli_test(eval_spheres_folder 3 ARGS eval ${link} ${work}/folder.txt
         STDERR "folder.txt: is a folder, not a file")
cli_test(batch_output_is_input 2 ARGS batch ${work} -o ${work} -q STDERR "is the input")
file(WRITE ${work}/comma.urdf "<robot name=\"r\"><link name=\"a\"><visual><geometry><box size=\"1 1 1\"/></geometry></visual><collision><origin xyz=\"0 0 0,2\"/><geometry><cylinder radius=\"0.025\" length=\"0.05\"/></geometry></collision></link></robot>\n")
cli_test(robot_malformed_collision 4 ARGS robot ${work}/comma.urdf -o ${work}/never37.yml -q
         STDERR "comma.urdf: link 'a': Unable to parse component .0,2." FORBID ${work}/never37.yml)
cli_test(robot_eval_link 0 ARGS eval ${robot}/three_link_description/meshes/link.stl
         ${work}/three.yml --link link1 --samples 1000 --segments 10 --shadow-resolution 0
         STDOUT "with [0-9]+ spheres")
set_tests_properties(cli.robot_eval_link PROPERTIES DEPENDS cli.robot_budget)
cli_test(robot_eval_unknown_link 2 ARGS eval ${robot}/three_link_description/meshes/link.stl
         ${work}/three.yml --link elbow STDERR "three.yml: no link 'elbow' .it has base_link")
set_tests_properties(cli.robot_eval_unknown_link PROPERTIES DEPENDS cli.robot_budget)
cli_test(robot_render 0 ARGS render ${robot}/three_link.urdf ${work}/three.yml --package-path
         ${robot} --joint-positions joint2=0.8 --size 320x240 -o ${work}/three.png
         FILE ${work}/three.png)
set_tests_properties(cli.robot_render PROPERTIES DEPENDS cli.robot_budget)
cli_test(robot_summary 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-spheres base_link=2 --link-spheres link1=2 --link-spheres link2=3 --quality fast
         -o ${work}/three_summary.json
         STDERR "link +triangles +repair +openings.*link2 +300 +none +0 +3 .*tool: no <collision> geometry, its <visual> geometry was used")
# The same robot file on one thread and on two (links are prepared and fitted in parallel).
cli_test(robot_one_thread 0 ARGS --threads 1 robot ${robot}/three_link.urdf --package-path
         ${robot} --budget 12 --quality fast -o ${work}/three_t1.yml -q FILE ${work}/three_t1.yml)
cli_test(robot_two_threads 0 ARGS --threads 2 robot ${robot}/three_link.urdf --package-path
         ${robot} --budget 12 --quality fast -o ${work}/three_t2.yml -q FILE ${work}/three_t2.yml)
add_test(NAME cli.robot_same_on_any_thread_count
         COMMAND ${CMAKE_COMMAND} -E compare_files ${work}/three_t1.yml ${work}/three_t2.yml)
set_tests_properties(cli.robot_same_on_any_thread_count PROPERTIES
                     DEPENDS "cli.robot_one_thread;cli.robot_two_threads")
cli_test(robot_budget_summary 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --budget 12 --quality fast -o ${work}/three_budget.yml
         STDERR "budget: outside volume [0-9.e-]+ of the links it split .split by curves [0-9.e-]+.")

# Several outputs of one fit; the self-collision pairs by sampling the joint space.
cli_test(robot_srdf 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot} --quality fast
         -o ${work}/three.srdf -o ${work}/three_srdf.json -o ${work}/three.lula.yml
         --collision-samples 500
         STDERR "self-collision: 3 adjacent, 0 default, 0 always, [0-9]+ never, [0-9]+ of 6 pairs left to check .500 configurations on the spheres"
         FILE ${work}/three.srdf)
cli_test(robot_lula 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot} --quality fast
         -o ${work}/three_lula.lula.yaml -o ${work}/three_lula.yml --joint-positions joint2=0.5 -q
         FILE ${work}/three_lula.lula.yaml)
cli_test(robot_collision_json 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --quality fast -o ${work}/three_collision.json --collision-check meshes
         --collision-seed 7 --always-fraction 0.9 --json -q
         STDOUT "\"self_collision\":{\"adjacent\":3,\"always\":[0-9]+,\"check\":\"meshes\",.*\"samples\":4000")
cli_test(robot_bad_collision_samples 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --collision-samples -5 -o ${work}/never38.srdf -q
         STDERR "collision_samples '-5': expected an integer from 0 to 10000000"
         FORBID ${work}/never38.srdf)
cli_test(robot_bad_collision_seed 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --collision-seed -1 -o ${work}/never39.srdf -q
         STDERR "collision_seed '-1': expected an integer from 0 to 18446744073709551615"
         FORBID ${work}/never39.srdf)
cli_test(robot_bad_always_fraction 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --always-fraction 0.2 -o ${work}/never40.srdf -q
         STDERR "always_fraction '0.2': expected a number from 0.5 to 1"
         FORBID ${work}/never40.srdf)
cli_test(robot_bad_collision_check 2 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} --collision-check fcl -o ${work}/never41.srdf -q
         STDERR "collision_check 'fcl': expected spheres or meshes" FORBID ${work}/never41.srdf)
cli_test(robot_output_twice 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         -o ${work}/never42.srdf -o ${work}/../cli/never42.srdf -q
         STDERR "never42.srdf: given twice as an output" FORBID ${work}/never42.srdf)
# Every output is checked before the fit: a bad second output leaves no first.
cli_test(robot_second_output_unwritable 6 ARGS robot ${robot}/three_link.urdf --package-path
         ${robot} -o ${work}/never43.srdf -o ${work}/no/such/folder/x.yml -q
         STDERR "x.yml: the folder .* does not exist" FORBID ${work}/never43.srdf)

cli_test(robot_skip_link 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-spheres link1=0 --link-spheres tool=0 --quality fast -o ${work}/three_skip.yml
         STDERR "link1 +0 - +0 +0 +0.0000 +0.0000 +0 +skipped.*tool +0 - +0 +0 +0.0000 +0.0000 +0 +skipped")
cli_test(robot_fractional_count 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-spheres link1=2.5 -o ${work}/never35.yml -q
         STDERR "link_spheres .link1=2.5.: expected LINK=VALUE, VALUE an integer from 0 to 1000000" FORBID ${work}/never35.yml)

# eval with the URDF as MESH measures the link's geometry as placed (link2's mesh has an origin
# and a scale, so the raw file would not be covered).
cli_test(robot_eval_urdf_link 0 ARGS eval ${robot}/three_link.urdf ${work}/three.yml --link link2
         --package-path ${robot} --samples 1000 --segments 0 --shadow-resolution 0
         STDOUT "surface covered  yes")
set_tests_properties(cli.robot_eval_urdf_link PROPERTIES DEPENDS cli.robot_budget)
cli_test(robot_eval_urdf_needs_link 2 ARGS eval ${robot}/three_link.urdf ${work}/three.yml
         --package-path ${robot} STDERR "three_link.urdf: a URDF needs --link LINK")
cli_test(robot_eval_urdf_walls_openings 2 ARGS eval ${robot}/three_link.urdf ${work}/three.yml
         --link link2 --package-path ${robot} --link-solid walls --fill-openings 0.1
         STDERR "three_link.urdf: every link's solid is its walls: fill_openings 0.1 asks for an envelope")
# One link's solid decided apart (--link-solid-for): link2's envelope at the size given, the
# others' walls; eval and robot make the same solid from the same flags. A name the robot lacks
# is refused.
if(SPHERESET_WITH_REPAIR)
  cli_test(robot_link_solid_for 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
           --link-solid walls --fill-openings 0.05 --link-solid-for link2=envelope
           --link-spheres base_link=1 --link-spheres link1=2 --link-spheres link2=2
           --quality fast -o ${work}/solid_for.yml --json -q
           STDOUT "\"fill_openings\":0.0,\"fitted\":true,\"from_visual\":false,\"limit_met\":true,\"link\":\"link1\".*\"fill_openings\":0.05,\"fitted\":true,\"from_visual\":false,\"limit_met\":true,\"link\":\"link2\"")
  cli_test(robot_eval_link_solid_for 0 ARGS eval ${robot}/three_link.urdf ${work}/solid_for.yml
           --link link2 --package-path ${robot} --link-solid walls --fill-openings 0.05
           --link-solid-for link2=envelope --samples 1000 --segments 0 --shadow-resolution 0 --json
           STDOUT "\"solid\":\"envelope\".*\"surface_covered\":true")
  set_tests_properties(cli.robot_eval_link_solid_for PROPERTIES DEPENDS cli.robot_link_solid_for)
endif()
cli_test(robot_link_solid_for_unknown 2 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
         --link-solid-for elbow=walls -o ${work}/never_solid_for.yml
         STDERR "link_solid_for names 'elbow', not a link of three_link"
         FORBID ${work}/never_solid_for.yml)
cli_test(robot_eval_link_solid_for_bad 2 ARGS eval ${robot}/three_link.urdf ${work}/never_read.yml
         --link link2 --package-path ${robot} --link-solid-for link2=hollow
         STDERR "link_solid_for 'link2=hollow': expected LINK=VALUE, VALUE envelope or walls")

# The posed robot against obstacles. Spheres by hand: link2's sphere (0.45, 0, 0) r 0.05 is at
# (0.45, 0, 0.5) at zero and at (0.45 cos q, 0, 0.5 - 0.45 sin q) at joint2 = q; the obstacle
# sphere r 0.02 sits where it is at q = 0.4, reached first by waypoint 2 of 0, 0.2, 0.4, 0.6.
set(q ${work}/query_robot)
file(MAKE_DIRECTORY ${q})
file(WRITE ${q}/hand.yml "collision_spheres:\n  base_link:\n    - center: [0, 0, 0.05]\n      radius: 0.1\n  link2:\n    - center: [0.45, 0, 0]\n      radius: 0.05\n")
file(WRITE ${q}/elbow.yml "collision_spheres:\n  elbow:\n    - center: [0, 0, 0]\n      radius: 0.1\n")
file(WRITE ${q}/cloud.xyz "# x y z\n0.45 0 0.52\n5 5 5\n")
file(WRITE ${q}/nan.xyz "0 0 0\n0.45 nan 0.52\n")
file(WRITE ${q}/obstacles.txt "0.4144775 0 0.3247619 0.02\n5 5 5 0.1\n")
file(WRITE ${q}/negative.txt "0 0 0 -1\n")
file(WRITE ${q}/traj.csv "joint2,joint1\n0,0\n0.2,0\n0.4,0\n0.6,0\n")
file(WRITE ${q}/unknown_joint.csv "joint2,joint9\n0,0\n")
file(WRITE ${q}/not_a_number.csv "joint2\n0\nabc\n")
file(WRITE ${q}/ragged.csv "joint1,joint2\n0,0\n0,0,0\n")
file(WRITE ${q}/empty.csv "")
set(qr query ${robot}/three_link.urdf ${q}/hand.yml --package-path ${robot})
cli_test(query_robot_points 0 ARGS ${qr} --points ${q}/cloud.xyz
         STDOUT "base_link: clear.*link2: collides, signed distance -0.03 .sphere 0, obstacle 0.*robot: collides")
cli_test(query_robot_json 0 ARGS ${qr} --points ${q}/cloud.xyz --joint-positions joint2=1 --json
         STDOUT "^\\{.*\"collides\":false.*\"link\":\"link2\".*\"kind\":\"points\"")
cli_test(query_robot_trajectory 0 ARGS ${qr} --spheres ${q}/obstacles.txt --trajectory ${q}/traj.csv
         STDOUT "waypoints: 4, first collision at waypoint 2: link2 sphere 0 with obstacle 0")
cli_test(query_robot_trajectory_json 0 ARGS ${qr} --spheres ${q}/obstacles.txt --trajectory
         ${q}/traj.csv --json
         STDOUT "\"first_collision\":\\{[^}]*\"link\":\"link2\"[^}]*\"waypoint\":2\\}.*\"per_waypoint\":\\[\\{\"collides\":false")
cli_test(query_robot_sphere_urdf 0 ARGS query ${robot}/three_link.urdf ${work}/three_spheres.urdf
         --package-path ${robot} --points ${q}/cloud.xyz
         STDOUT "base_link: clear, signed distance [0-9.]+ .sphere.*link1: .*link2: .*tool: .*robot: ")
set_tests_properties(cli.query_robot_sphere_urdf PROPERTIES DEPENDS cli.robot_urdf)
cli_test(query_robot_unknown_joint_csv 4 ARGS ${qr} --points ${q}/cloud.xyz --trajectory
         ${q}/unknown_joint.csv STDERR "unknown_joint.csv:1: no joint 'joint9' in robot 'three_link'"
         STDOUT "^$")
cli_test(query_robot_not_a_number_csv 4 ARGS ${qr} --points ${q}/cloud.xyz --trajectory
         ${q}/not_a_number.csv STDERR "not_a_number.csv:3: joint 'joint2': 'abc' is not a finite number")
cli_test(query_robot_ragged_csv 4 ARGS ${qr} --points ${q}/cloud.xyz --trajectory ${q}/ragged.csv
         STDERR "ragged.csv:3: 3 values, the header names 2 joints")
cli_test(query_robot_empty_csv 4 ARGS ${qr} --points ${q}/cloud.xyz --trajectory ${q}/empty.csv
         STDERR "empty.csv: empty, expected a header row of joint names")
cli_test(query_robot_nan_point 4 ARGS ${qr} --points ${q}/nan.xyz STDERR "nan.xyz:2 .*finite"
         STDOUT "^$")
cli_test(query_robot_negative_radius 4 ARGS ${qr} --spheres ${q}/negative.txt
         STDERR "negative.txt:1: .*negative")
cli_test(query_robot_unknown_link 4 ARGS query ${robot}/three_link.urdf ${q}/elbow.yml
         --package-path ${robot} --points ${q}/cloud.xyz
         STDERR "elbow.yml: link 'elbow' is not a link of robot 'three_link'")
cli_test(query_robot_unknown_joint 2 ARGS ${qr} --points ${q}/cloud.xyz --joint-positions joint9=1
         STDERR "--joint-positions: no joint 'joint9' in robot")
cli_test(query_robot_no_obstacles 2 ARGS ${qr} STDERR "needs obstacles: --points CLOUD or --spheres")
cli_test(query_robot_missing_cloud 3 ARGS ${qr} --points ${q}/missing.xyz STDERR "missing.xyz")
cli_test(query_robot_point_option 2 ARGS ${qr} --points ${q}/cloud.xyz --point 0,0,0
         STDERR "--point, --segment and --other query a sphere set")
cli_test(query_set_robot_option 2 ARGS query ${work}/bound.txt --points ${q}/cloud.xyz
         STDERR "bound.txt: a second file, --points.* need a robot")
cli_test(robot_render_link 0 ARGS render ${robot}/three_link.urdf ${q}/hand.yml --package-path
         ${robot} --link link2 --size 160x120 -o ${q}/link2.png FILE ${q}/link2.png)
cli_test(robot_render_bad_link 2 ARGS render ${robot}/three_link.urdf ${q}/hand.yml --package-path
         ${robot} --link elbow -o ${q}/never_link.png
         STDERR "three_link.urdf: no link 'elbow' in robot 'three_link' .it has base_link"
         FORBID ${q}/never_link.png)
cli_test(robot_render_unknown_link_spheres 4 ARGS render ${robot}/three_link.urdf ${q}/elbow.yml
         --package-path ${robot} -o ${q}/never_elbow.png
         STDERR "elbow.yml: link 'elbow' is not a link of robot 'three_link'"
         FORBID ${q}/never_elbow.png)

# MJCF robots (MuJoCo): in and out, with the written model read back by eval, view and query; a
# bad MJCF gives MuJoCo's own message with its line (exit 4) and nothing is written. Without
# MuJoCo in the build, an .xml robot is refused with the reason (exit 3).
set(mjcf ${robot}/mjcf/arm.xml)
if(SPHERESET_WITH_MUJOCO)
  cli_test(robot_mjcf 0 ARGS robot ${mjcf} --default-link-spheres 4 --quality fast
           --collision-samples 500 -o ${work}/arm_spheres.xml -o ${work}/arm_spheres.yml --json -q
           FILE ${work}/arm_spheres.xml
           STDOUT "\"link\":\"wrist\".*\"covered\":true.*\"never\":[1-9]")
  cli_test(robot_mjcf_eval_link 0 ARGS eval ${mjcf} ${work}/arm_spheres.yml --link wrist
           --samples 1000 --segments 0 --shadow-resolution 0 STDOUT "surface covered  yes")
  set_tests_properties(cli.robot_mjcf_eval_link PROPERTIES DEPENDS cli.robot_mjcf)
  cli_test(robot_mjcf_view_page 0 ARGS view ${mjcf} ${work}/arm_spheres.xml
           --html ${work}/arm_spheres.html FILE ${work}/arm_spheres.html)
  set_tests_properties(cli.robot_mjcf_view_page PROPERTIES DEPENDS cli.robot_mjcf)
  cli_test(robot_mjcf_query 0 ARGS query ${mjcf} ${work}/arm_spheres.xml --points ${q}/cloud.xyz
           --joint-positions j1=0.3,fl=0.02
           STDOUT "world: .*base: .*wrist: .*finger_left: .*robot: ")
  set_tests_properties(cli.robot_mjcf_query PROPERTIES DEPENDS cli.robot_mjcf)
  cli_test(robot_mjcf_render 0 ARGS render ${mjcf} ${work}/arm_spheres.yml
           -o ${work}/arm_spheres.png --joint-positions j2=0.5 FILE ${work}/arm_spheres.png)
  set_tests_properties(cli.robot_mjcf_render PROPERTIES DEPENDS cli.robot_mjcf)
  cli_test(robot_mjcf_group 0 ARGS robot ${mjcf} --collision-group 2 --default-link-spheres 2
           --quality fast --collision-samples 100 -o ${work}/arm_group.json -q
           FILE ${work}/arm_group.json)
  cli_test(robot_mjcf_bad_group 2 ARGS robot ${mjcf} --collision-group 9 -o ${work}/never36.xml -q
           STDERR "collision group must be from 0 to 5" FORBID ${work}/never36.xml)
  file(WRITE ${work}/broken_mjcf.xml "<mujoco>\n<worldbody>\n<geom type='box' size='1 1'>\n</worldbody></mujoco>\n")
  cli_test(robot_mjcf_broken 4 ARGS robot ${work}/broken_mjcf.xml -o ${work}/never37.xml -q
           STDERR "broken_mjcf.xml: MuJoCo: .*Line number=3" FORBID ${work}/never37.xml)
  cli_test(robot_urdf_to_mjcf 0 ARGS robot ${robot}/three_link.urdf --package-path ${robot}
           --default-link-spheres 3 --quality fast --collision-samples 200
           -o ${work}/three_spheres.xml -q FILE ${work}/three_spheres.xml)
else()
  cli_test(robot_mjcf_missing 3 ARGS robot ${mjcf} -o ${work}/never36.yml -q
           STDERR "arm.xml: this build of sphereset reads no MJCF" FORBID ${work}/never36.yml)
endif()
