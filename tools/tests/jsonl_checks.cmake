# Checks shared by the uv_unwrap batch scripts (included by them).
#
# check_jsonl_line(K LINE STATUS INPUT_REGEX): LINE, the K-th line of a
# --jsonl file, parses as JSON, has status STATUS and an input matching
# INPUT_REGEX, and, where STATUS is ok, describes a valid atlas (no flipped
# face, no crossing border, no overlap area, UVs in the unit square). Fails
# the script otherwise.
function(check_jsonl_line k line want_status want_input)
  string(JSON got_status ERROR_VARIABLE parse_error GET "${line}" status)
  if(parse_error)
    message(FATAL_ERROR "line ${k} is not JSON: ${parse_error}")
  endif()
  string(JSON got_input GET "${line}" input)
  if(NOT got_status STREQUAL want_status OR NOT got_input MATCHES "${want_input}")
    message(FATAL_ERROR "line ${k}: input ${got_input}, status ${got_status}; expected ${want_input}, ${want_status}")
  endif()
  if(want_status STREQUAL "ok")
    string(JSON flips GET "${line}" flipped_faces)
    string(JSON crossings GET "${line}" border_crossings)
    string(JSON overlap GET "${line}" overlap_area)
    string(JSON in_square GET "${line}" uv_in_unit_square)
    if(NOT flips EQUAL 0 OR NOT crossings EQUAL 0 OR NOT overlap EQUAL 0 OR NOT in_square)
      message(FATAL_ERROR "line ${k}: not a valid atlas: ${line}")
    endif()
  endif()
endfunction()
