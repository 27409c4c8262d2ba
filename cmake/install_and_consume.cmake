# The test install_and_consume (ctest, cmake/install.cmake): installs this
# build into WORK_DIR/prefix, configures examples/ as a separate project
# against it (find_package(dda CONFIG REQUIRED), nothing of this build tree
# on its paths), builds it, runs its tests, and runs the installed `dda`.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DCXX=... -DBUILD_TYPE=... -DVERSION=...
#         -P install_and_consume.cmake
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_and_consume: ${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(consumer ${WORK_DIR}/consumer)
file(REMOVE_RECURSE ${WORK_DIR})

run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/dda/simulation.hpp include/dda/cdem/model.hpp include/dda/io/scene_file.hpp
          bin/dda share/dda/SCHEMA.md share/dda/scenes/two_squares.json)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install_and_consume: ${prefix}/${f} was not installed")
  endif()
endforeach()
file(GLOB_RECURSE configs ${prefix}/*/ddaConfig.cmake)
if(NOT configs)
  message(FATAL_ERROR "install_and_consume: no ddaConfig.cmake under ${prefix}")
endif()
file(GLOB_RECURSE internal ${prefix}/include/*internal*)
if(internal)
  message(FATAL_ERROR "install_and_consume: internal headers installed: ${internal}")
endif()

# The consumer sees the prefix only: no package registry, no build tree.
run("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${consumer}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DDDA_EXAMPLE_SCENES=${prefix}/share/dda/scenes)
file(STRINGS ${consumer}/CMakeCache.txt dda_dir REGEX "^dda_DIR:")
string(FIND "${dda_dir}" "${prefix}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "install_and_consume: the consumer found dda outside the prefix: ${dda_dir}")
endif()
run("build the consumer" ${CMAKE_COMMAND} --build ${consumer})
run("test the consumer" ${CMAKE_CTEST_COMMAND} --test-dir ${consumer} --output-on-failure)
message(STATUS "${out}")

run("dda --version" ${prefix}/bin/dda --version)
if(NOT out MATCHES "^dda ${VERSION} \\(commit [^)]+\\)")
  message(FATAL_ERROR "install_and_consume: unexpected 'dda --version': ${out}")
endif()
message(STATUS "${out}")
run("dda check" ${prefix}/bin/dda check ${prefix}/share/dda/scenes/two_squares.json)
message(STATUS "${out}")
file(REMOVE_RECURSE ${WORK_DIR})
