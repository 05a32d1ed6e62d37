# Ctrl-C: uv_unwrap gets SIGINT (coreutils' timeout) one second into a run
# that takes several (--max-distortion 4.2 on the default mesh: 10 s in
# Release). It must stop with exit status 130, say it was canceled, and
# leave no mesh behind; its --stats file says ERROR_CANCELED.
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -P interrupt.cmake
cmake_minimum_required(VERSION 3.19) # string(JSON)
if(NOT UV_UNWRAP OR NOT WORK_DIR)
  message(FATAL_ERROR "give -DUV_UNWRAP=... -DWORK_DIR=...")
endif()
find_program(TIMEOUT timeout)
if(NOT TIMEOUT)
  message(FATAL_ERROR "coreutils' timeout is needed to send the signal")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(mesh "${WORK_DIR}/out.obj")
set(stats "${WORK_DIR}/stats.json")
execute_process(COMMAND "${TIMEOUT}" -s INT --preserve-status 1
                        "${UV_UNWRAP}" --max-distortion 4.2 -o "${mesh}" --stats "${stats}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(context "stdout:\n${out}\nstderr:\n${err}")
if(NOT status EQUAL 130)
  message(FATAL_ERROR "exit status ${status}, expected 130 (interrupted)\n${context}")
endif()
if(NOT err MATCHES "ERROR_CANCELED|interrupted")
  message(FATAL_ERROR "the run does not say it was canceled\n${context}")
endif()
if(EXISTS "${mesh}")
  message(FATAL_ERROR "an interrupted run left ${mesh}\n${context}")
endif()
file(READ "${stats}" json)
string(JSON run_status GET "${json}" status)
if(NOT run_status STREQUAL "ERROR_CANCELED")
  message(FATAL_ERROR "statistics status ${run_status}, expected ERROR_CANCELED")
endif()
message(STATUS "interrupted: exit status 130, no mesh written, status ERROR_CANCELED")
