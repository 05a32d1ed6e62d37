# Ctrl-C: uv_unwrap gets SIGINT (coreutils' timeout) one second into a run
# that takes several (--max-distortion 4.2 on the default mesh: 10 s in
# Release). It must stop with exit status 130, say it was canceled, and
# leave no mesh behind; its --stats file says ERROR_CANCELED. Run twice:
# timeout signals the process and then its group (two SIGINTs at once), and a
# shell sends two SIGINTs back to back: both are one request, not a kill.
#   cmake -DUV_UNWRAP=<exe> -DWORK_DIR=<dir> -P interrupt.cmake
cmake_minimum_required(VERSION 3.19) # string(JSON)
if(NOT UV_UNWRAP OR NOT WORK_DIR)
  message(FATAL_ERROR "give -DUV_UNWRAP=... -DWORK_DIR=...")
endif()
find_program(TIMEOUT timeout)
if(NOT TIMEOUT)
  message(FATAL_ERROR "coreutils' timeout is needed to send the signal")
endif()
find_program(SHELL_PROGRAM sh)
if(NOT SHELL_PROGRAM)
  message(FATAL_ERROR "a POSIX shell is needed to send the signals")
endif()
set(mesh "${WORK_DIR}/out.obj")
set(stats "${WORK_DIR}/stats.json")
set(arguments --max-distortion 4.2 -o "${mesh}" --stats "${stats}")
string(REPLACE ";" "' '" quoted "'${UV_UNWRAP}' '${arguments}'")
foreach(sender timeout shell)
  file(REMOVE_RECURSE "${WORK_DIR}")
  file(MAKE_DIRECTORY "${WORK_DIR}")
  if(sender STREQUAL "timeout")
    execute_process(COMMAND "${TIMEOUT}" -s INT --preserve-status 1 "${UV_UNWRAP}" ${arguments}
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  else()
    execute_process(COMMAND "${SHELL_PROGRAM}" -c
                            "${quoted} & pid=$!; sleep 1; kill -INT $pid; kill -INT $pid; wait $pid"
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  endif()
  set(context "signals sent by ${sender}\nstdout:\n${out}\nstderr:\n${err}")
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
    message(FATAL_ERROR "statistics status ${run_status}, expected ERROR_CANCELED (${sender})")
  endif()
  message(STATUS "interrupted by ${sender}: exit status 130, no mesh written, status ERROR_CANCELED")
endforeach()
