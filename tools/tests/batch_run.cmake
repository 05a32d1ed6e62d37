# uv_unwrap's batch mode on a directory holding two good meshes and a broken
# one: the good ones are written, the broken one is reported, the run goes
# on, the exit status is the number of failures and the JSON Lines file has
# one line per input.
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -P batch_run.cmake
if(NOT UV_UNWRAP OR NOT WORK_DIR)
  message(FATAL_ERROR "give -DUV_UNWRAP=... -DWORK_DIR=...")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/jsonl_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/in")

# a square of 2 x 2 quads (OBJ) and a tetrahedron (OFF), and a broken file
file(WRITE "${WORK_DIR}/in/a_square.obj"
  "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0.2\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
  "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n")
file(WRITE "${WORK_DIR}/in/b_broken.obj" "v 0 0 0\nv 1 0 0\nf 1 2 7\n")
file(WRITE "${WORK_DIR}/in/c_tetrahedron.off"
  "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
file(WRITE "${WORK_DIR}/in/notes.txt" "not a mesh: left out\n")

execute_process(COMMAND "${UV_UNWRAP}" "${WORK_DIR}/in" --output-dir "${WORK_DIR}/out"
                        --jsonl "${WORK_DIR}/stats.jsonl" -q
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1 (one failed input); stderr:\n${errors}")
endif()
if(NOT errors MATCHES "b_broken.obj")
  message(FATAL_ERROR "the broken input is not named on stderr:\n${errors}")
endif()
foreach(out a_square_uv.obj c_tetrahedron_uv.obj)
  if(NOT EXISTS "${WORK_DIR}/out/${out}")
    message(FATAL_ERROR "${out} was not written")
  endif()
endforeach()
if(EXISTS "${WORK_DIR}/out/b_broken_uv.obj")
  message(FATAL_ERROR "an output was written for the broken input")
endif()

file(STRINGS "${WORK_DIR}/stats.jsonl" lines)
list(LENGTH lines count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "${count} JSON lines, expected 3:\n${lines}")
endif()
set(expected_status ok ERROR_CANNOT_READ ok)
set(expected_input a_square.obj b_broken.obj c_tetrahedron.off)
foreach(k RANGE 2)
  list(GET lines ${k} line)
  list(GET expected_status ${k} want_status)
  list(GET expected_input ${k} want_input)
  check_jsonl_line(${k} "${line}" ${want_status} "${want_input}$")
  if(NOT want_status STREQUAL "ok")
    string(JSON distortion_type TYPE "${line}" distortion)
    if(NOT distortion_type STREQUAL "NULL")
      message(FATAL_ERROR "line ${k}: a failed input reports a distortion: ${line}")
    endif()
  endif()
endforeach()

# the same inputs as files, two of the same name: the second one fails
file(MAKE_DIRECTORY "${WORK_DIR}/other")
file(COPY "${WORK_DIR}/in/a_square.obj" DESTINATION "${WORK_DIR}/other")
execute_process(COMMAND "${UV_UNWRAP}" "${WORK_DIR}/in/a_square.obj" "${WORK_DIR}/other/a_square.obj"
                        --output-dir "${WORK_DIR}/out2" -q
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 1 OR NOT errors MATCHES "same name")
  message(FATAL_ERROR "two inputs of the same name: exit status ${status}, stderr:\n${errors}")
endif()
message(STATUS "batch run: 2 of 3 inputs unwrapped, the broken one reported, exit status 1")
