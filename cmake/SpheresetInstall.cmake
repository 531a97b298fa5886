# `cmake --install`: the library (and the GPL sphereset_repair when built), the public headers,
# the sphereset command, a CMake package (find_package(sphereset), targets sphereset::sphereset
# and sphereset::repair) and sphereset.pc for pkg-config.
#
# The library is static by default (BUILD_SHARED_LIBS=ON builds it shared) and compiled as
# position-independent code, so that it can also go into shared objects such as the Python
# module. Its dependencies other than Eigen (whose types appear in the public headers) are
# private: a shared library hides them; a static one needs them at link time, so the package
# finds them for the consumer (find_dependency) and sphereset.pc lists them.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SPHERESET_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/sphereset)
set(spheresetInstallTargets sphereset)
set_target_properties(sphereset PROPERTIES POSITION_INDEPENDENT_CODE ON
                                           VERSION ${PROJECT_VERSION} SOVERSION 0)
target_include_directories(sphereset PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
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
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
else()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/sphereset
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN repair_cgal.hpp EXCLUDE)
endif()
install(EXPORT spheresetTargets NAMESPACE sphereset:: FILE spheresetTargets.cmake
  DESTINATION ${SPHERESET_INSTALL_CMAKEDIR})

# What the package's config has to find for a consumer.
if(BUILD_SHARED_LIBS)
  set(SPHERESET_STATIC_DEPENDENCIES "")
  set(SPHERESET_STATIC_REPAIR_DEPENDENCIES "")
else()
  set(SPHERESET_STATIC_DEPENDENCIES [[
find_dependency(TBB)
find_dependency(assimp)
find_dependency(nlohmann_json 3.10)
find_dependency(NLopt)
find_dependency(PNG)
find_dependency(yaml-cpp)
find_dependency(urdfdom)]])
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
set(SPHERESET_PC_DEPENDENCIES "tbb assimp nlopt libpng yaml-cpp urdfdom")
if(BUILD_SHARED_LIBS)
  set(SPHERESET_PC_REQUIRES "eigen3")
  set(SPHERESET_PC_REQUIRES_PRIVATE "${SPHERESET_PC_DEPENDENCIES}")
  set(SPHERESET_PC_LIBS "-lsphereset")
else()
  set(SPHERESET_PC_REQUIRES "eigen3 ${SPHERESET_PC_DEPENDENCIES}")
  set(SPHERESET_PC_REQUIRES_PRIVATE "")
  set(SPHERESET_PC_LIBS "-lsphereset")
endif()
# Relocatable: the prefix is found from the .pc file's own folder.
file(RELATIVE_PATH SPHERESET_PC_TO_PREFIX
  ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SPHERESET_PC_TO_PREFIX "${SPHERESET_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/sphereset.pc.in ${PROJECT_BINARY_DIR}/sphereset.pc
  @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/sphereset.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
