# cut_param_link_optional_libraries(<target> [BUILD_ONLY])
#
# Finds the optional libraries of the cut-parameterization package and links
# those found to the INTERFACE target <target>, with the macro that turns
# each one on in the headers:
#   CHOLMOD (Debian: libsuitesparse-dev)  CGAL_SMP_CUT_USE_CHOLMOD, if CUT_PARAM_USE_CHOLMOD
#   METIS   (Debian: libmetis-dev)        CGAL_SMP_CUT_USE_METIS,   if CUT_PARAM_USE_METIS
#   TBB     (Debian: libtbb-dev)          CGAL_LINKED_WITH_TBB,     if CUT_PARAM_USE_TBB
# The options default to ON. Used by the project's CMakeLists.txt (BUILD_ONLY:
# not written to the installed package, which finds them again) and by the
# installed CGAL_Cut_parameterizationConfig.cmake.
option(CUT_PARAM_USE_CHOLMOD "Use SuiteSparse CHOLMOD (supernodal) for large systems when found" ON)
option(CUT_PARAM_USE_METIS "Order large sparse systems with METIS when found" ON)
option(CUT_PARAM_USE_TBB "Use TBB when found" ON)

function(cut_param_link_optional_libraries target)
  cmake_parse_arguments(ARG "BUILD_ONLY" "" "" ${ARGN})
  # a library without CMake package: header and library file
  function(_cut_param_use name header library define fallback)
    find_path(${name}_INCLUDE_DIR ${header} PATH_SUFFIXES ${ARGN})
    find_library(${name}_LIBRARY ${library})
    if(${name}_INCLUDE_DIR AND ${name}_LIBRARY)
      message(STATUS "${name} found: ${${name}_LIBRARY}")
      set(include_dir ${${name}_INCLUDE_DIR})
      set(lib ${${name}_LIBRARY})
      if(ARG_BUILD_ONLY)
        set(include_dir $<BUILD_INTERFACE:${include_dir}>)
        set(lib $<BUILD_INTERFACE:${lib}>)
        set(define $<BUILD_INTERFACE:${define}>)
      endif()
      target_include_directories(${target} INTERFACE ${include_dir})
      target_link_libraries(${target} INTERFACE ${lib})
      target_compile_definitions(${target} INTERFACE ${define})
    else()
      message(STATUS "${name} not found: ${fallback}")
    endif()
  endfunction()

  if(CUT_PARAM_USE_CHOLMOD)
    _cut_param_use(CHOLMOD cholmod.h cholmod CGAL_SMP_CUT_USE_CHOLMOD
                   "(Debian: libsuitesparse-dev) Eigen's sparse Cholesky at every size" suitesparse)
  endif()
  if(CUT_PARAM_USE_METIS)
    _cut_param_use(METIS metis.h metis CGAL_SMP_CUT_USE_METIS "(Debian: libmetis-dev) AMD ordering at every size")
  endif()
  if(CUT_PARAM_USE_TBB)
    find_package(TBB QUIET)
    if(TBB_FOUND)
      include(CGAL_TBB_support)
      if(ARG_BUILD_ONLY)
        target_link_libraries(${target} INTERFACE $<BUILD_INTERFACE:CGAL::TBB_support>)
      else()
        target_link_libraries(${target} INTERFACE CGAL::TBB_support)
      endif()
    endif()
  endif()
endfunction()
