# Install rules and the CMake package `dda`:
#
#   cmake --install build --prefix P      (or: make install PREFIX=P)
#
# puts the headers in P/include/dda, the libraries in P/lib (dda, dda_cdem,
# dda_io), the command `dda` in P/bin, the example scenes and the scene-file
# schema in P/share/dda, and the package in P/lib/cmake/dda, so that
# another project writes
#
#   find_package(dda CONFIG REQUIRED)          # with -DCMAKE_PREFIX_PATH=P
#   target_link_libraries(app PRIVATE dda::dda)  # or dda::cdem, dda::io
#
# dda::dda is Paper A's solver and geometry, dda::cdem Paper B's model,
# dda::io the scene files; dda::command is the `dda` executable. The
# package's config finds Eigen (the headers use it) and OpenMP (when the
# library was built with it). The test install_and_consume builds examples/
# against such an install.
include(CMakePackageConfigHelpers)
set(DDA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dda)

install(TARGETS dda dda_cdem dda_csv dda_io dda_cli
        EXPORT ddaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Public headers only (the internal ones stay in lib/src and lib/cdem/src).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/dda
                  ${PROJECT_SOURCE_DIR}/lib/cdem/include/dda
                  ${PROJECT_SOURCE_DIR}/lib/io/include/dda
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/repro/scenes DESTINATION ${CMAKE_INSTALL_DATADIR}/dda FILES_MATCHING PATTERN "*.json")
install(FILES ${PROJECT_SOURCE_DIR}/lib/io/SCHEMA.md DESTINATION ${CMAKE_INSTALL_DATADIR}/dda)

install(EXPORT ddaTargets NAMESPACE dda:: DESTINATION ${DDA_INSTALL_CMAKEDIR})
get_target_property(dda_interface_libs dda INTERFACE_LINK_LIBRARIES)
if("OpenMP::OpenMP_CXX" IN_LIST dda_interface_libs)
  set(DDA_WITH_OPENMP ON)
else()
  set(DDA_WITH_OPENMP OFF)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ddaConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/ddaConfig.cmake
                              INSTALL_DESTINATION ${DDA_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ddaConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ddaConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/ddaConfigVersion.cmake
        DESTINATION ${DDA_INSTALL_CMAKEDIR})

# ctest: install into a temporary prefix, then configure, build and test
# examples/ as a separate project against it (and run the installed dda).
if(DDA_BUILD_TESTS)
  add_test(NAME install_and_consume
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                   -DWORK_DIR=${CMAKE_BINARY_DIR}/install_test -DCXX=${CMAKE_CXX_COMPILER}
                   -DBUILD_TYPE=${CMAKE_BUILD_TYPE} -DVERSION=${PROJECT_VERSION}
                   -P ${CMAKE_CURRENT_LIST_DIR}/install_and_consume.cmake)
  set_tests_properties(install_and_consume PROPERTIES LABELS install)
endif()
