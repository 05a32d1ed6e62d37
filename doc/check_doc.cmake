# Runs Doxygen and checks its output; used by the `doc` target and the
# `doc_builds` test (doc/CMakeLists.txt).
#
#   cmake -DDOXYGEN=... -DDOXYFILE=... -DOUTPUT_DIR=... -DHEADER=...
#         [-DFAIL_ON_WARNINGS=ON] [-DCHECK_TABLES=ON] -P check_doc.cmake
#
# FAIL_ON_WARNINGS: fail unless Doxygen's warning log (WARN_LOGFILE) is empty.
# CHECK_TABLES: in the generated HTML, every documented function whose
# signature takes `const NamedParameters&` has a named-parameter table
# (\cgalNamedParamsBegin), the functions below list at least the named
# parameters given here, and every named parameter that HEADER declares
# (CGAL_SMP_CUT_NAMED_PARAMETER) is in some function's table.

cmake_minimum_required(VERSION 3.16)

foreach(_var DOXYGEN DOXYFILE OUTPUT_DIR)
  if(NOT ${_var})
    message(FATAL_ERROR "check_doc.cmake: ${_var} is not set")
  endif()
endforeach()

set(_log "${OUTPUT_DIR}/doxygen_warnings.log")
file(REMOVE "${_log}")
# no stale page of an earlier run may pass the checks below
file(REMOVE_RECURSE "${OUTPUT_DIR}/html")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}"
                WORKING_DIRECTORY "${OUTPUT_DIR}"
                RESULT_VARIABLE _status)
set(_warnings "")
if(EXISTS "${_log}")
  file(READ "${_log}" _warnings)
  string(STRIP "${_warnings}" _warnings)
endif()
if(_warnings)
  string(REGEX MATCHALL "\n" _lines "${_warnings}\n")
  list(LENGTH _lines _count)
  message("${_warnings}")
  message("Doxygen: ${_count} warning line(s), in ${_log}")
  if(FAIL_ON_WARNINGS)
    message(FATAL_ERROR "Doxygen reported warnings")
  endif()
else()
  message(STATUS "Doxygen: 0 warnings")
endif()
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "Doxygen failed (exit status ${_status})")
endif()

if(NOT CHECK_TABLES)
  return()
endif()

# Named parameters each function's table must list (name|np1,np2,...).
set(_expected
  "cut_and_parameterize()|cut_parameterization_options,lambda,face_lambda_map,forbidden_seam_edge_map,distortion_bound,epsilon_start,epsilon_end,iterations_per_epsilon,gamma,number_of_passes,minimum_relative_cut_length,number_of_iterations,multiresolution_faces,inner_solver,reject_degenerate_faces,global_injectivity,texture_size,padding,world_units,bounding_box_aspect_ratio,bounding_box_stiffness,bounding_box_distortion_budget,face_discontinuity_map,progress_callback,vertex_point_map"
  "cut_parameterization_options_from()|cut_parameterization_options,lambda,inner_solver,bounding_box_stiffness,progress_callback"
  "symmetric_dirichlet_parameterize()|vertex_point_map,face_weight_map,initialize_from_uv_map,number_of_iterations,stopping_tolerance"
  "face_visibility()|number_of_rays,maximum_distance,vertex_point_map,progress_callback"
  "face_distortion()|vertex_point_map,uv_scale"
  "distortion_energy()|vertex_point_map,uv_scale"
  "is_degenerate_face()|vertex_point_map"
  "surface_area()|vertex_point_map"
  "seam_length()|vertex_point_map"
  "write_OBJ_with_uvs()|vertex_point_map,vertex_index_map,stream_precision")

# The names in the table cells of one piece of HTML, as a list.
function(np_names html out)
  set(_names "")
  set(_rest "${html}")
  while(TRUE)
    string(FIND "${_rest}" "cgal-np-name\">" _at)
    if(_at EQUAL -1)
      break()
    endif()
    math(EXPR _at "${_at} + 14")
    string(SUBSTRING "${_rest}" ${_at} -1 _rest)
    string(FIND "${_rest}" "</td>" _end)
    string(SUBSTRING "${_rest}" 0 ${_end} _cell)
    string(REGEX REPLACE "<[^>]*>" "" _cell "${_cell}")
    string(STRIP "${_cell}" _cell)
    list(APPEND _names "${_cell}")
  endwhile()
  set(${out} "${_names}" PARENT_SCOPE)
endfunction()

# Every documented member of the HTML pages: its title and its text.
file(GLOB _pages "${OUTPUT_DIR}/html/*.html")
set(_errors "")
set(_all_names "")
set(_tables 0)
set(_seen_titles "")
foreach(_page IN LISTS _pages)
  file(READ "${_page}" _html)
  string(FIND "${_html}" "<h2 class=\"memtitle\">" _at)
  while(NOT _at EQUAL -1)
    string(SUBSTRING "${_html}" ${_at} -1 _html)
    string(SUBSTRING "${_html}" 21 -1 _html)
    string(FIND "${_html}" "<h2 class=\"memtitle\">" _next)
    if(_next EQUAL -1)
      set(_item "${_html}")
    else()
      string(SUBSTRING "${_html}" 0 ${_next} _item)
    endif()
    string(FIND "${_item}" "</h2>" _end)
    string(SUBSTRING "${_item}" 0 ${_end} _title)
    string(REGEX REPLACE "<span class=\"overload\">.*</span>" "" _title "${_title}")
    string(REGEX REPLACE "<[^>]*>" "" _title "${_title}")
    string(REGEX REPLACE "&#9670;(&nbsp;|&#160;)?" "" _title "${_title}")
    string(STRIP "${_title}" _title)
    np_names("${_item}" _names)
    if(_names)
      math(EXPR _tables "${_tables} + 1")
      list(APPEND _all_names ${_names})
    endif()
    get_filename_component(_page_name "${_page}" NAME)
    if(_item MATCHES "const NamedParameters &amp;" AND NOT _item MATCHES "cgal-named-params")
      list(APPEND _errors "${_page_name}: ${_title} takes named parameters but has no \\cgalNamedParamsBegin table")
    endif()
    foreach(_spec IN LISTS _expected)
      string(REPLACE "|" ";" _spec "${_spec}")
      list(GET _spec 0 _function)
      list(GET _spec 1 _wanted)
      if(_title STREQUAL _function)
        list(APPEND _seen_titles "${_function}")
        string(REPLACE "," ";" _wanted "${_wanted}")
        foreach(_name IN LISTS _wanted)
          if(NOT _name IN_LIST _names)
            list(APPEND _errors "${_page_name}: the table of ${_function} lacks the named parameter ${_name}")
          endif()
        endforeach()
      endif()
    endforeach()
    if(_next EQUAL -1)
      set(_at -1)
    else()
      set(_at ${_next})
    endif()
  endwhile()
endforeach()

foreach(_spec IN LISTS _expected)
  string(REPLACE "|" ";" _spec "${_spec}")
  list(GET _spec 0 _function)
  if(NOT _function IN_LIST _seen_titles)
    list(APPEND _errors "no documented function ${_function} in the HTML")
  endif()
endforeach()

# Every named parameter the package declares is documented in a table.
if(HEADER)
  file(READ "${HEADER}" _header)
  string(REGEX MATCHALL "\nCGAL_SMP_CUT_NAMED_PARAMETER\\([a-z_0-9]+, *[a-z_0-9]+\\)" _declared "${_header}")
  foreach(_decl IN LISTS _declared)
    string(REGEX REPLACE ".*, *([a-z_0-9]+)\\)" "\\1" _name "${_decl}")
    if(NOT _name IN_LIST _all_names)
      list(APPEND _errors "the named parameter ${_name} (${HEADER}) is in no function's table")
    endif()
  endforeach()
  list(LENGTH _declared _declared_count)
endif()

if(_errors)
  string(REPLACE ";" "\n  " _errors "${_errors}")
  message(FATAL_ERROR "Named-parameter tables:\n  ${_errors}")
endif()
list(REMOVE_DUPLICATES _all_names)
list(LENGTH _all_names _distinct)
message(STATUS "Named-parameter tables: ${_tables} functions, ${_distinct} distinct named parameters, "
               "${_declared_count} declared by the package, all documented")
