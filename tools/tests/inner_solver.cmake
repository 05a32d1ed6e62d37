# --inner-solver (a row of the option table) reaches the library: on the
# default mesh, the proxy quasi-Newton solver takes more iterations than
# Newton (L-BFGS steps between its factorizations) and another number of
# factorizations; --inner-solver newton is the default run; a name not in
# the table is refused.
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -P inner_solver.cmake
cmake_minimum_required(VERSION 3.19) # string(JSON)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run name)
  execute_process(COMMAND "${UV_UNWRAP}" -q -o "${WORK_DIR}/${name}.obj" --stats "${WORK_DIR}/${name}.json" ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "uv_unwrap ${ARGN}: exit status ${status}\n${out}${err}")
  endif()
  file(READ "${WORK_DIR}/${name}.json" json)
  foreach(key factorizations newton_iterations distortion seam_length)
    string(JSON value GET "${json}" ${key})
    set(${name}_${key} "${value}" PARENT_SCOPE)
  endforeach()
endfunction()

run(default)
run(newton --inner-solver newton)
run(proxy --inner-solver proxy-quasi-newton)
message(STATUS "default: ${default_factorizations} factorizations, ${default_newton_iterations} iterations; "
               "newton: ${newton_factorizations}, ${newton_newton_iterations}; "
               "proxy-quasi-newton: ${proxy_factorizations}, ${proxy_newton_iterations}")
foreach(key factorizations newton_iterations distortion seam_length)
  if(NOT default_${key} STREQUAL newton_${key})
    message(FATAL_ERROR "--inner-solver newton is not the default run: ${key} ${newton_${key}} != ${default_${key}}")
  endif()
endforeach()
if(NOT proxy_newton_iterations GREATER newton_newton_iterations OR proxy_factorizations EQUAL newton_factorizations)
  message(FATAL_ERROR "proxy-quasi-newton: ${proxy_newton_iterations} iterations and ${proxy_factorizations} "
                      "factorizations against Newton's ${newton_newton_iterations} and ${newton_factorizations}: "
                      "the choice did not reach the library")
endif()

execute_process(COMMAND "${UV_UNWRAP}" -q --inner-solver bfgs RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(status EQUAL 0 OR NOT "${out}${err}" MATCHES "--inner-solver: invalid value 'bfgs'")
  message(FATAL_ERROR "--inner-solver bfgs: exit status ${status}, not refused\n${out}${err}")
endif()
