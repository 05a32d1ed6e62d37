# Installs the project into a temporary prefix, then configures, builds and
# runs test/downstream (find_package(CGAL_Cut_parameterization)) against it.
#   cmake -DBUILD_DIR=<project build> -DSOURCE_DIR=<test/downstream> -DWORK_DIR=<scratch>
#         [-DBUILD_TYPE=Release] -P install_and_use.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "give -D${var}=...")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
file(REMOVE_RECURSE "${WORK_DIR}")

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
if(NOT EXISTS "${WORK_DIR}/prefix/include/CGAL/Surface_mesh_parameterization/cut_and_parameterize.h")
  message(FATAL_ERROR "the headers were not installed")
endif()
step("configure the downstream project"
     ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
     "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix")
step("build the downstream project" ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
step("run the downstream program" "${WORK_DIR}/build/unwrap_grid")
message(STATUS "downstream program: ${step_output}")
