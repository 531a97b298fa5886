# Command-line behaviour of `sphereset view` (included by cli_tests.cmake, whose cli_test, `cli`,
# `work`, `link` and `data` it uses): bad inputs refused with their one-line messages and exit
# codes before anything is served; --html writes the page with the scene inlined (or, in a
# build without the page, says so with exit 9); the server prints its address and stops
# cleanly on SIGTERM.
cli_test(view_missing_mesh 3 ARGS view ${work}/missing.off ${work}/bound.txt --html ${work}/never70.html
         STDERR "missing.off: no such file" FORBID ${work}/never70.html)
cli_test(view_bad_spheres 4 ARGS view ${link} ${work}/bad.txt --html ${work}/never71.html
         STDERR "bad.txt:1: expected four numbers" FORBID ${work}/never71.html)
cli_test(view_level_of_a_set 2 ARGS view ${link} ${work}/bound.txt --level 1 --no-open
         STDERR "bound.txt: a sphere set has no levels")
cli_test(view_bad_port 2 ARGS view ${link} ${work}/bound.txt --port 70000 --no-open)
cli_test(view_html_over_input 2 ARGS view ${link} ${work}/bound.txt --html ${work}/bound.txt
         STDERR "bound.txt")
cli_test(view_open_mesh 5 ARGS view ${work}/open.off ${work}/bound.txt --repair off --no-open
         STDERR "open.off: not a closed solid")
cli_test(view_robot_unknown_link 4 ARGS view ${data}/robot/three_link.urdf ${work}/view_elbow.yml
         --package-path ${data}/robot --link-solid walls --no-open
         STDERR "link 'elbow' is not a link of three_link")
file(WRITE ${work}/view_elbow.yml "collision_spheres:\n  elbow:\n    - center: [0, 0, 0]\n      radius: 0.1\n")
add_test(NAME cli.view_html
         COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DMESH=${link} -DSPHERES=${work}/bound.txt
           -DOUT=${work}/view.html -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
add_test(NAME cli.view_serves_until_sigterm
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/view_serve.sh ${cli} ${link} ${work}/bound.txt)
file(WRITE ${work}/view_robot.yml "collision_spheres:\n  link1:\n    - center: [0, 0, 0.2]\n      radius: 0.25\n  link2:\n    - center: [0.1, -0.2, 0.3]\n      radius: 0.4\n")
add_test(NAME cli.view_html_robot
         COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DMESH=${data}/robot/three_link.urdf
           -DSPHERES=${work}/view_robot.yml -DOUT=${work}/view_robot.html
           "-DEXTRA=--package-path|${data}/robot|--link-solid|walls" -DSOLIDS=2
           -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
# The pages of `sphereset robot -o ROBOT.html` (a static page of the fit, one solid per link with
# spheres) and of `sphereset batch --html` (one beside each item's sphere file).
add_test(NAME cli.robot_html
         COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DOUT=${work}/robot_page.html -DSOLIDS=3
           "-DARGS=robot|${data}/robot/three_link.urdf|--package-path|${data}/robot|--budget|8|--quality|fast|-q|-o|${work}/robot_page.yml|-o|${work}/robot_page.json|-o|${work}/robot_page.html"
           -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
# The page's link solids follow --link-solid-for as the fit's do: with every other link's walls
# and a size given, a page that ignored it would have no envelope for the size and be refused.
if(SPHERESET_WITH_REPAIR)
  add_test(NAME cli.robot_html_link_solid_for
           COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DOUT=${work}/robot_solid_for.html -DSOLIDS=3
             "-DARGS=robot|${data}/robot/three_link.urdf|--package-path|${data}/robot|--link-solid|walls|--fill-openings|0.05|--link-solid-for|link2=envelope|--quality|fast|-q|-o|${work}/robot_solid_for.html"
             -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
endif()
file(COPY ${link} DESTINATION ${work}/batch_pages)
add_test(NAME cli.batch_html
         COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DOUT=${work}/batch_pages_out/fr3_link1_collision.html
           -DSOLIDS=1
           "-DARGS=batch|${work}/batch_pages|-o|${work}/batch_pages_out|-n|4|--quality|fast|-q|--html"
           -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
# The robot's JSON report as the spheres of a view (read per link); written without a page, so
# that a build without the page (where `robot -o X.html` stops with exit 9) has it too.
cli_test(robot_report_for_view 0 ARGS robot ${data}/robot/three_link.urdf --package-path
         ${data}/robot --budget 8 --quality fast -q -o ${work}/robot_for_view.json
         FILE ${work}/robot_for_view.json)
add_test(NAME cli.view_html_robot_report
         COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DMESH=${data}/robot/three_link.urdf
           -DSPHERES=${work}/robot_for_view.json -DOUT=${work}/robot_report.html
           "-DEXTRA=--package-path|${data}/robot" -DSOLIDS=3
           -P ${CMAKE_CURRENT_LIST_DIR}/view_html.cmake)
set_tests_properties(cli.view_html_robot_report PROPERTIES DEPENDS cli.robot_report_for_view)
