# `cmake --install`: the library (and the GPL sphereset_repair when built), the public headers,
# the sphereset command, a CMake package (find_package(sphereset), the umbrella target
# sphereset::sphereset, one target per component: core, io, render, robot, animate, batch, and
# sphereset::repair) and sphereset.pc for pkg-config.
#
# The library is static by default (BUILD_SHARED_LIBS=ON builds it shared) and compiled as
# position-independent code, so that it can also go into shared objects such as the Python
# module. Its dependencies other than Eigen (whose types appear in the public headers) are
# private: a shared library hides them; a static one needs them at link time, so the package
# finds them for the consumer (find_dependency) and sphereset.pc lists them.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SPHERESET_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/sphereset)
# The stage libraries (src/CMakeLists.txt) and the umbrella target sphereset::sphereset.
set(SPHERESET_COMPONENT_TARGETS sphereset_core sphereset_io sphereset_render sphereset_robot
  sphereset_animate sphereset_batch)
set(spheresetInstallTargets sphereset ${SPHERESET_COMPONENT_TARGETS})
foreach(t IN LISTS SPHERESET_COMPONENT_TARGETS)
  set_target_properties(${t} PROPERTIES POSITION_INDEPENDENT_CODE ON
    VERSION ${PROJECT_VERSION} SOVERSION 0)
endforeach()
target_include_directories(sphereset_core PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
if(SPHERESET_WITH_REPAIR)
  set_target_properties(sphereset_repair PROPERTIES EXPORT_NAME repair
    POSITION_INDEPENDENT_CODE ON VERSION ${PROJECT_VERSION} SOVERSION 0)
  list(APPEND spheresetInstallTargets sphereset_repair)
endif()
# The installed command finds an installed shared library beside it.
set_target_properties(sphereset_cli PROPERTIES
  INSTALL_RPATH "$<$<BOOL:${BUILD_SHARED_LIBS}>:$ORIGIN/../${CMAKE_INSTALL_LIBDIR}>")

install(TARGETS ${spheresetInstallTargets} EXPORT spheresetTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS sphereset_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(SPHERESET_WITH_REPAIR)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/sphereset
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN view.hpp EXCLUDE)
else()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/sphereset
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN repair_cgal.hpp EXCLUDE PATTERN view.hpp EXCLUDE)
endif()
install(EXPORT spheresetTargets NAMESPACE sphereset:: FILE spheresetTargets.cmake
  DESTINATION ${SPHERESET_INSTALL_CMAKEDIR})

# What the package's config has to find for a consumer.
if(BUILD_SHARED_LIBS)
  set(SPHERESET_STATIC_DEPENDENCIES "")
  set(SPHERESET_STATIC_REPAIR_DEPENDENCIES "")
else()
  # Per component: what its static library needs at the consumer's link (the core: TBB, NLopt,
  # CBC through pkg-config).
  set(SPHERESET_STATIC_DEPENDENCIES [[
find_dependency(TBB)
find_dependency(NLopt)
find_dependency(PkgConfig)
pkg_check_modules(CBC REQUIRED IMPORTED_TARGET cbc)
if(NOT sphereset_FIND_COMPONENTS OR "io" IN_LIST _sphereset_wanted)
  find_dependency(assimp)
  find_dependency(nlohmann_json 3.10)
  find_dependency(yaml-cpp)
endif()
if(NOT sphereset_FIND_COMPONENTS OR "render" IN_LIST _sphereset_wanted)
  find_dependency(PNG)
endif()
if(NOT sphereset_FIND_COMPONENTS OR "robot" IN_LIST _sphereset_wanted)
  find_dependency(urdfdom)
endif()]])
  set(SPHERESET_STATIC_REPAIR_DEPENDENCIES "find_dependency(CGAL 5.5)")
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/spheresetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/spheresetConfig.cmake INSTALL_DESTINATION ${SPHERESET_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/spheresetConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/spheresetConfig.cmake
  ${PROJECT_BINARY_DIR}/spheresetConfigVersion.cmake DESTINATION ${SPHERESET_INSTALL_CMAKEDIR})

# pkg-config: a static library's dependencies are part of `pkg-config --libs sphereset`; a shared
# one's are private.
set(SPHERESET_PC_DEPENDENCIES "tbb assimp nlopt cbc libpng yaml-cpp urdfdom tinyxml")
# Later stages first, as a static link needs them.
set(SPHERESET_PC_LIBRARIES
  "-lsphereset_batch -lsphereset_animate -lsphereset_robot -lsphereset_render -lsphereset_io -lsphereset_core")
if(BUILD_SHARED_LIBS)
  set(SPHERESET_PC_REQUIRES "eigen3")
  set(SPHERESET_PC_REQUIRES_PRIVATE "${SPHERESET_PC_DEPENDENCIES}")
  set(SPHERESET_PC_LIBS "${SPHERESET_PC_LIBRARIES}")
else()
  set(SPHERESET_PC_REQUIRES "eigen3 ${SPHERESET_PC_DEPENDENCIES}")
  set(SPHERESET_PC_REQUIRES_PRIVATE "")
  set(SPHERESET_PC_LIBS "${SPHERESET_PC_LIBRARIES}")
  if(SPHERESET_WITH_MUJOCO)
    string(APPEND SPHERESET_PC_LIBS " -lmujoco")  # MuJoCo has no pkg-config file
  endif()
endif()
# Relocatable: the prefix is found from the .pc file's own folder.
file(RELATIVE_PATH SPHERESET_PC_TO_PREFIX
  ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SPHERESET_PC_TO_PREFIX "${SPHERESET_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/sphereset.pc.in ${PROJECT_BINARY_DIR}/sphereset.pc
  @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/sphereset.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
