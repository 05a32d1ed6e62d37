# uv_unwrap's BLAS kernels (tools/blas_setup.h): where OpenBLAS falls back
# to its generic "Prescott" kernels on a processor with AVX2 and FMA, the
# program starts again on vector kernels, once (its output is not repeated);
# a kernel set in OPENBLAS_CORETYPE by the user is kept. OpenBLAS says which
# kernels it loads with OPENBLAS_VERBOSE=2 ("Core: <name>"); without such a
# line the BLAS is not OpenBLAS and the test is skipped (its
# SKIP_REGULAR_EXPRESSION matches "nothing to check").
#   cmake -DUV_UNWRAP=<exe> -P blas_kernels.cmake
if(NOT UV_UNWRAP)
  message(FATAL_ERROR "give -DUV_UNWRAP=...")
endif()
set(ENV{OPENBLAS_VERBOSE} 2)
unset(ENV{OPENBLAS_CORETYPE})

function(run_help out_cores out_helps)
  execute_process(COMMAND "${UV_UNWRAP}" --help RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "uv_unwrap --help: exit status ${status}\n${err}")
  endif()
  string(REGEX MATCHALL "Core: [A-Za-z0-9]+" cores "${out}${err}")
  string(REGEX MATCHALL "Usage:" helps "${out}")
  list(LENGTH helps n)
  set(${out_cores} "${cores}" PARENT_SCOPE)
  set(${out_helps} ${n} PARENT_SCOPE)
endfunction()

run_help(cores helps)
if(NOT cores)
  message(STATUS "no 'Core:' line: the BLAS is not OpenBLAS, nothing to check")
  return()
endif()
if(NOT helps EQUAL 1)
  message(FATAL_ERROR "the help was printed ${helps} times, expected once")
endif()
list(GET cores -1 last)
file(READ /proc/cpuinfo cpuinfo LIMIT 20000)
if(cpuinfo MATCHES "flags[^\n]* avx2( |\n)" AND cpuinfo MATCHES "flags[^\n]* fma( |\n)")
  if(last STREQUAL "Core: Prescott")
    message(FATAL_ERROR "AVX2 and FMA present, yet the run ended on OpenBLAS's Prescott kernels (${cores})")
  endif()
  list(LENGTH cores loads)
  if(loads GREATER 2)
    message(FATAL_ERROR "the program started ${loads} times (${cores}), at most twice expected")
  endif()
endif()
message(STATUS "kernels: ${cores}")

# the user's choice is kept: one start, on the kernels asked for
set(ENV{OPENBLAS_CORETYPE} Prescott)
run_help(cores helps)
if(NOT cores STREQUAL "Core: Prescott" OR NOT helps EQUAL 1)
  message(FATAL_ERROR "with OPENBLAS_CORETYPE=Prescott: '${cores}', help printed ${helps} times; expected one start on Prescott")
endif()
