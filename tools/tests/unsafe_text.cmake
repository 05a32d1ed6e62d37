# Text from files and paths reaching JSON and the terminal: a batch over a
# directory holding 4 KB of random bytes named .obj, a valid mesh whose file
# name is Latin-1 (caf\xe9.obj, not UTF-8) and a good mesh. Every input gets
# a JSON line that parses, the random file a clean error, the Latin-1 name
# an escaped name and a valid atlas, and the batch goes on after the bad
# file; stderr holds no byte that is not UTF-8. Then --stats on the random
# file alone: a JSON file that parses, with the error in it.
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -P unsafe_text.cmake
if(NOT UV_UNWRAP OR NOT WORK_DIR)
  message(FATAL_ERROR "give -DUV_UNWRAP=... -DWORK_DIR=...")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/jsonl_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/in")

# 4096 random bytes (1..255; CMake strings hold no NUL), the same each run
set(alphabet "")
foreach(c RANGE 1 255)
  string(ASCII ${c} byte)
  string(APPEND alphabet "${byte}")
endforeach()
string(RANDOM LENGTH 4096 ALPHABET "${alphabet}" RANDOM_SEED 43 random_bytes)
file(WRITE "${WORK_DIR}/in/a_random.obj" "${random_bytes}")
string(ASCII 233 latin1_e_acute)
file(WRITE "${WORK_DIR}/in/b_caf${latin1_e_acute}.obj"
  "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0.2\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
  "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n")
file(WRITE "${WORK_DIR}/in/c_tetrahedron.off"
  "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")

execute_process(COMMAND "${UV_UNWRAP}" "${WORK_DIR}/in" --output-dir "${WORK_DIR}/out"
                        --jsonl "${WORK_DIR}/stats.jsonl" -q
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1 (the random file fails, the batch goes on); stderr:\n${errors}")
endif()
if(errors MATCHES "${latin1_e_acute}")
  message(FATAL_ERROR "stderr echoes the raw Latin-1 byte")
endif()
if(NOT errors MATCHES "a_random\\.obj")
  message(FATAL_ERROR "the random file is not named on stderr:\n${errors}")
endif()
foreach(out "b_caf${latin1_e_acute}_uv.obj" c_tetrahedron_uv.obj)
  if(NOT EXISTS "${WORK_DIR}/out/${out}")
    message(FATAL_ERROR "${out} was not written: the batch stopped")
  endif()
endforeach()

file(STRINGS "${WORK_DIR}/stats.jsonl" lines)
list(LENGTH lines count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "${count} JSON lines, expected 3")
endif()
set(expected_status ERROR_CANNOT_READ ok ok)
set(expected_input "a_random\\.obj$" "b_caf\\\\xe9\\.obj$" "c_tetrahedron\\.off$")
foreach(k RANGE 2)
  list(GET lines ${k} line)
  list(GET expected_status ${k} want_status)
  list(GET expected_input ${k} want_input)
  check_jsonl_line(${k} "${line}" ${want_status} "${want_input}")
  if(NOT want_status STREQUAL "ok")
    string(JSON message GET "${line}" error)
    if(NOT message MATCHES "cannot read")
      message(FATAL_ERROR "line ${k}: no clean error message: ${line}")
    endif()
  endif()
endforeach()

# one file, its statistics in a JSON file
execute_process(COMMAND "${UV_UNWRAP}" "${WORK_DIR}/in/a_random.obj" -o "${WORK_DIR}/random_uv.obj"
                        --stats "${WORK_DIR}/random.json"
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 1)
  message(FATAL_ERROR "--stats on the random file: exit status ${status}, expected 1; stderr:\n${errors}")
endif()
file(READ "${WORK_DIR}/random.json" stats)
string(JSON got_status ERROR_VARIABLE parse_error GET "${stats}" status)
if(parse_error OR NOT got_status STREQUAL "ERROR_CANNOT_READ")
  message(FATAL_ERROR "--stats on the random file: ${parse_error} ${got_status}\n${stats}")
endif()
message(STATUS "random bytes and a Latin-1 name: clean errors and escaped names in JSON, the batch went on")
