# The pipeline order as a build rule (src/README.md). A file of one stage may include the private
# headers of its own stage and of earlier stages, and the public headers that those stages own;
# a public header may include the public headers of its own and earlier stages. Anything else
# stops the configuration and the build (the target sphereset_stage_check runs this script on
# every build: cmake -DSPHERESET_SOURCE_DIR=... -P cmake/SpheresetStages.cmake).
#
# The stages form the library targets (src/CMakeLists.txt): util to tree are sphereset_core,
# which needs only Eigen, TBB and NLopt; io, render, robot, animate and batch are one target
# each; repair_cgal is sphereset_repair.

cmake_minimum_required(VERSION 3.25)

set(SPHERESET_STAGES
  util index mesh repair cover fit eval tree io render robot animate batch repair_cgal)

# The public headers (include/sphereset/NAME.hpp) each stage owns. mesh.hpp holds the plain
# data every stage shares (Vec3, Mesh, Aabb) with the mesh stage's functions, so it is the
# util stage's.
set(SPHERESET_PUBLIC_util status limits options sphere mesh)
set(SPHERESET_PUBLIC_index solid_index)
set(SPHERESET_PUBLIC_mesh mesh_defects)
set(SPHERESET_PUBLIC_repair repair)
set(SPHERESET_PUBLIC_cover cover)
set(SPHERESET_PUBLIC_fit fit)
set(SPHERESET_PUBLIC_eval evaluate)
set(SPHERESET_PUBLIC_tree query sphere_tree tree)
set(SPHERESET_PUBLIC_io load sphere_io export)
set(SPHERESET_PUBLIC_render render)
set(SPHERESET_PUBLIC_robot robot robot_fit)
set(SPHERESET_PUBLIC_animate animate)
set(SPHERESET_PUBLIC_batch batch)
set(SPHERESET_PUBLIC_repair_cgal repair_cgal)

# Appends to the list `out_var` each include of `file` (of stage `stage`) that breaks the order.
function(sphereset_stage_includes file stage out_var)
  list(FIND SPHERESET_STAGES ${stage} rank)
  file(STRINGS ${file} lines REGEX "^#include \"[a-z_0-9]+/[a-z_0-9]+\\.hpp\"")
  set(found ${${out_var}})
  foreach(line IN LISTS lines)
    string(REGEX MATCH "^#include \"([a-z_0-9]+)/([a-z_0-9]+)\\.hpp\"" _ "${line}")
    set(folder ${CMAKE_MATCH_1})
    set(name ${CMAKE_MATCH_2})
    set(owner "")
    if(folder STREQUAL "sphereset")
      foreach(s IN LISTS SPHERESET_STAGES)
        if(name IN_LIST SPHERESET_PUBLIC_${s})
          set(owner ${s})
        endif()
      endforeach()
      if(owner STREQUAL "")
        list(APPEND found "${file}: sphereset/${name}.hpp is owned by no stage (cmake/SpheresetStages.cmake)")
        continue()
      endif()
    else()
      set(owner ${folder})
    endif()
    list(FIND SPHERESET_STAGES ${owner} owner_rank)
    if(owner_rank GREATER rank)
      list(APPEND found "${file}: stage ${stage} includes ${folder}/${name}.hpp of the later stage ${owner}")
    endif()
  endforeach()
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()

function(sphereset_check_stages source_dir)
  set(problems "")
  foreach(stage IN LISTS SPHERESET_STAGES)
    file(GLOB files ${source_dir}/src/${stage}/*.cpp ${source_dir}/src/${stage}/*.hpp)
    foreach(name IN LISTS SPHERESET_PUBLIC_${stage})
      if(EXISTS ${source_dir}/include/sphereset/${name}.hpp)
        list(APPEND files ${source_dir}/include/sphereset/${name}.hpp)
      endif()
    endforeach()
    foreach(f IN LISTS files)
      sphereset_stage_includes(${f} ${stage} problems)
    endforeach()
  endforeach()
  file(GLOB public ${source_dir}/include/sphereset/*.hpp)
  foreach(f IN LISTS public)
    get_filename_component(name ${f} NAME_WE)
    set(owned FALSE)
    foreach(s IN LISTS SPHERESET_STAGES)
      if(name IN_LIST SPHERESET_PUBLIC_${s})
        set(owned TRUE)
      endif()
    endforeach()
    if(NOT owned)
      list(APPEND problems "${f}: a public header owned by no stage (cmake/SpheresetStages.cmake)")
    endif()
  endforeach()
  if(problems)
    list(JOIN problems "\n  " text)
    message(FATAL_ERROR "The pipeline order (src/README.md) is broken:\n  ${text}")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND SPHERESET_SOURCE_DIR)
  sphereset_check_stages(${SPHERESET_SOURCE_DIR})
endif()
