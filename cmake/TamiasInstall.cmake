# Install and package rules: the libraries with their public headers, the CMake package
# (find_package(tamias2d 0.2 CONFIG)), pkg-config files, the CLI and the user documentation.
include(CMakePackageConfigHelpers)

set(TAMIAS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tamias2d)
set(targets tamias2d)
if(TARGET tamias2d_io)
  list(APPEND targets tamias2d_io)
endif()
install(TARGETS ${targets} EXPORT tamias2dTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/tamias2d DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development)
install(FILES ${PROJECT_BINARY_DIR}/include/tamias2d/version.hpp
              ${PROJECT_BINARY_DIR}/include/tamias2d/config.hpp
              ${PROJECT_BINARY_DIR}/include/tamias2d/export.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tamias2d COMPONENT development)
if(TARGET tamias2d_io)
  install(FILES ${PROJECT_BINARY_DIR}/include/tamias2d/io/export.hpp
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tamias2d/io COMPONENT development)
endif()
install(EXPORT tamias2dTargets NAMESPACE tamias2d:: DESTINATION ${TAMIAS_CMAKE_DIR}
        COMPONENT development)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tamias2dConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/tamias2dConfig.cmake
                              INSTALL_DESTINATION ${TAMIAS_CMAKE_DIR})
# 0.x: a new minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tamias2dConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tamias2dConfig.cmake
              ${PROJECT_BINARY_DIR}/tamias2dConfigVersion.cmake
        DESTINATION ${TAMIAS_CMAKE_DIR} COMPONENT development)

# Relocatable: the prefix is found from the .pc file's own place.
file(RELATIVE_PATH TAMIAS_PC_TO_PREFIX /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
string(REGEX REPLACE "/$" "" TAMIAS_PC_TO_PREFIX "${TAMIAS_PC_TO_PREFIX}")
foreach(pc tamias2d tamias2d-io)
  if(pc STREQUAL "tamias2d-io" AND NOT TARGET tamias2d_io)
    continue()
  endif()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT development)
endforeach()

if(TARGET tamias2d_cli)
  install(TARGETS tamias2d_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/docs/user-guide.md
              ${PROJECT_SOURCE_DIR}/docs/scene-format.md ${PROJECT_SOURCE_DIR}/docs/scene.schema.json
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/scenes DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        COMPONENT development)
install(FILES ${PROJECT_SOURCE_DIR}/apps/examples/two_bodies.cpp
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples COMPONENT development)

# A Debian package of the same files: `cpack -G DEB` in the build directory.
set(CPACK_PACKAGE_NAME tamias2d)
set(CPACK_PACKAGE_VENDOR "Tamias2D")
set(CPACK_PACKAGE_CONTACT "Tamias2D maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
include(CPack)
