# One uv_unwrap run whose exit status and outputs are both checked (CTest's
# PASS_REGULAR_EXPRESSION alone would ignore the exit status: a crash after
# the matching line, or a refusal that exits 0, would pass).
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -DARGS="<arg>|<arg>|..."
#         [-DEXPECT_STATUS=<n>] [-DEXPECT_OUTPUT=<regex>] [-DMAX_DISTORTION=<E_d>]
#         -P run_uv_unwrap.cmake
# ARGS: uv_unwrap's arguments separated by '|'. EXPECT_OUTPUT: a regular
# expression that stdout and stderr together must match.
# EXPECT_STATUS 0 (the default): uv_unwrap writes WORK_DIR/out.obj and
# WORK_DIR/stats.json (-o, --stats, added here); the run must exit 0, write
# an OBJ with UVs, and its statistics must say: status ok, no flipped face,
# no border crossing, no overlap area, UVs in the unit square, and E_d at
# most MAX_DISTORTION when given.
# EXPECT_STATUS n > 0: a refusal; the run must exit with n and write no mesh.
cmake_minimum_required(VERSION 3.19) # string(JSON)
if(NOT UV_UNWRAP OR NOT WORK_DIR)
  message(FATAL_ERROR "give -DUV_UNWRAP=... -DWORK_DIR=... [-DARGS=a|b]")
endif()
if(NOT DEFINED EXPECT_STATUS)
  set(EXPECT_STATUS 0)
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
string(REPLACE "|" ";" args "${ARGS}")
set(mesh "${WORK_DIR}/out.obj")
set(stats "${WORK_DIR}/stats.json")

execute_process(COMMAND "${UV_UNWRAP}" ${args} -o "${mesh}" --stats "${stats}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(both "${out}${err}")
set(context "uv_unwrap ${args}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT status STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_STATUS}\n${context}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT both MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "the output does not match '${EXPECT_OUTPUT}'\n${context}")
endif()

if(NOT EXPECT_STATUS EQUAL 0)
  if(EXISTS "${mesh}")
    message(FATAL_ERROR "a refused run wrote ${mesh}\n${context}")
  endif()
  message(STATUS "refused with exit status ${status}, no mesh written")
  return()
endif()

if(NOT EXISTS "${mesh}" OR NOT EXISTS "${stats}")
  message(FATAL_ERROR "${mesh} or ${stats} was not written\n${context}")
endif()
file(STRINGS "${mesh}" uv_lines REGEX "^vt ")
list(LENGTH uv_lines uv_count)
if(uv_count EQUAL 0)
  message(FATAL_ERROR "${mesh} has no UV (vt) line\n${context}")
endif()
file(READ "${stats}" json)
string(JSON run_status GET "${json}" status)
string(JSON in_square GET "${json}" uv_in_unit_square)
string(JSON distortion GET "${json}" distortion)
set(problems "")
if(NOT run_status STREQUAL "ok")
  list(APPEND problems "status ${run_status}")
endif()
foreach(key flipped_faces border_crossings overlap_area)
  string(JSON value GET "${json}" ${key})
  if(NOT value EQUAL 0)
    list(APPEND problems "${key} ${value}")
  endif()
endforeach()
if(NOT in_square)
  list(APPEND problems "UVs outside the unit square")
endif()
if(DEFINED MAX_DISTORTION AND NOT distortion LESS_EQUAL MAX_DISTORTION)
  list(APPEND problems "E_d ${distortion} above ${MAX_DISTORTION}")
endif()
if(problems)
  message(FATAL_ERROR "not a valid atlas: ${problems}\n${context}")
endif()
message(STATUS "exit status 0, ${uv_count} UVs, E_d ${distortion}, no flip, crossing or overlap")
