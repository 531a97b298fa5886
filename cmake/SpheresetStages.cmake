# The pipeline order as a build rule (src/README.md). A file of one stage may include the private
# headers of its own stage and of the stages it may use (the core stages before it, or the list
# below), and the public headers those stages own; a public header likewise; a core file no
# header of assimp, yaml-cpp, JSON, PNG, urdfdom, TinyXML or CGAL. Anything else
# stops the configuration and the build (the target sphereset_stage_check runs this script on
# every build: cmake -DSPHERESET_SOURCE_DIR=... -P cmake/SpheresetStages.cmake).
#
# The stages form the library targets (src/CMakeLists.txt): util to tree are sphereset_core,
# which needs only Eigen, TBB and NLopt; io, render, robot, animate and batch are one target
# each; view (the interactive page's server) is sphereset_view; repair_cgal is sphereset_repair.

cmake_minimum_required(VERSION 3.25)

set(SPHERESET_STAGES
  util index mesh repair cover fit eval tree io render robot animate batch view repair_cgal)
set(SPHERESET_CORE_STAGES util index mesh repair cover fit eval tree)

# The stages each later stage may use besides its own (the targets form a tree, not a line):
# a core stage may use the core stages before it.
set(SPHERESET_USES_io ${SPHERESET_CORE_STAGES})
set(SPHERESET_USES_render ${SPHERESET_CORE_STAGES} io)
set(SPHERESET_USES_robot ${SPHERESET_CORE_STAGES} io)
set(SPHERESET_USES_animate ${SPHERESET_CORE_STAGES} io)
set(SPHERESET_USES_batch ${SPHERESET_CORE_STAGES} io)
set(SPHERESET_USES_view ${SPHERESET_CORE_STAGES} io robot)
set(SPHERESET_USES_repair_cgal ${SPHERESET_CORE_STAGES})

# Libraries of other projects the core may not include (it links Eigen, TBB and NLopt only).
set(SPHERESET_NOT_IN_CORE assimp yaml-cpp nlohmann png urdf tinyxml CGAL)

# The public headers (include/sphereset/NAME.hpp) each stage owns. mesh.hpp holds the plain
# data every stage shares (Vec3, Mesh, Aabb) with the mesh stage's functions, so it is the
# util stage's.
set(SPHERESET_PUBLIC_util status exit_codes limits options sphere mesh)
set(SPHERESET_PUBLIC_index solid_index)
set(SPHERESET_PUBLIC_mesh mesh_defects)
set(SPHERESET_PUBLIC_repair repair)
set(SPHERESET_PUBLIC_cover cover)
set(SPHERESET_PUBLIC_fit fit)
set(SPHERESET_PUBLIC_eval evaluate result_fields certificate)
set(SPHERESET_PUBLIC_tree query sphere_tree tree)
set(SPHERESET_PUBLIC_io load sphere_io export)
set(SPHERESET_PUBLIC_render render)
set(SPHERESET_PUBLIC_robot robot robot_fit robot_query robot_collision)
set(SPHERESET_PUBLIC_animate animate)
set(SPHERESET_PUBLIC_batch batch)
set(SPHERESET_PUBLIC_view view)
set(SPHERESET_PUBLIC_repair_cgal repair_cgal)

# The stages `stage` may use: itself, the core stages before it (core), or its list above.
function(sphereset_stage_uses stage out_var)
  list(FIND SPHERESET_CORE_STAGES ${stage} core_rank)
  if(core_rank GREATER_EQUAL 0)
    set(uses "")
    foreach(s IN LISTS SPHERESET_CORE_STAGES)
      list(APPEND uses ${s})
      if(s STREQUAL stage)
        break()
      endif()
    endforeach()
  else()
    set(uses ${stage} ${SPHERESET_USES_${stage}})
  endif()
  set(${out_var} ${uses} PARENT_SCOPE)
endfunction()

# Appends to the list `out_var` each include of `file` (of stage `stage`) that breaks the order.
# Every form of the directive counts: quotes or angle brackets, spaces after '#', relative
# paths ("../io/x.hpp").
function(sphereset_stage_includes file stage out_var)
  sphereset_stage_uses(${stage} uses)
  list(FIND SPHERESET_CORE_STAGES ${stage} core_rank)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  set(found ${${out_var}})
  foreach(line IN LISTS lines)
    string(REGEX MATCH "include[ \t]*[<\"]([^>\"]+)[>\"]" _ "${line}")
    set(header ${CMAKE_MATCH_1})
    if(core_rank GREATER_EQUAL 0)
      foreach(lib IN LISTS SPHERESET_NOT_IN_CORE)
        if(header MATCHES "^${lib}[/.]" OR header MATCHES "^${lib}$")
          list(APPEND found "${file}: core stage ${stage} includes <${header}> (${lib})")
        endif()
      endforeach()
    endif()
    string(REGEX REPLACE "^(\\.\\./)+" "" header "${header}")
    if(NOT header MATCHES "^([a-z_0-9]+)/([a-z_0-9]+)\\.(hpp|h|inl)$")
      continue()
    endif()
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
    elseif(folder IN_LIST SPHERESET_STAGES)
      set(owner ${folder})
    else()
      continue()  # another project's header (Eigen/, tbb/, CLI/, ...)
    endif()
    if(NOT owner IN_LIST uses)
      list(APPEND found "${file}: stage ${stage} includes ${header} of the stage ${owner}, which it may not use")
    endif()
  endforeach()
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()

function(sphereset_check_stages source_dir)
  set(problems "")
  foreach(stage IN LISTS SPHERESET_STAGES)
    file(GLOB_RECURSE files ${source_dir}/src/${stage}/*.cpp ${source_dir}/src/${stage}/*.hpp
      ${source_dir}/src/${stage}/*.h ${source_dir}/src/${stage}/*.inl)
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
