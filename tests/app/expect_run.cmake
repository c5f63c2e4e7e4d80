# expect_run(CODE TEXT ARGS...): runs ${APP} ARGS, checks the exit code and that TEXT is in the
# output; for a failure, that the last stderr line is the error and names it. The output is left
# in `last_output`.
function(expect_run expected_code expected_text)
  execute_process(COMMAND ${APP} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  set(last_output "${out}${err}" PARENT_SCOPE)
  if (NOT code STREQUAL "${expected_code}")
    message(FATAL_ERROR "clothtrack ${ARGN}: exit ${code}, expected ${expected_code}\nstdout: ${out}\nstderr: ${err}")
  endif ()
  string(FIND "${out}${err}" "${expected_text}" pos)
  if (pos EQUAL -1)
    message(FATAL_ERROR "clothtrack ${ARGN}: output lacks '${expected_text}'\nstdout: ${out}\nstderr: ${err}")
  endif ()
  if (NOT expected_code EQUAL 0)
    # A user error ends with one readable line that says it all (progress lines may precede it).
    string(STRIP "${err}" stripped)
    string(REGEX REPLACE "^.*\n" "" last_line "${stripped}")
    string(FIND "${last_line}" "${expected_text}" pos)
    if (pos EQUAL -1 OR NOT last_line MATCHES "^clothtrack")
      message(FATAL_ERROR "clothtrack ${ARGN}: last stderr line is not the error:\n${err}")
    endif ()
  endif ()
endfunction()

# expect_early_error(TEXT ARGS...): as expect_run(1 TEXT ARGS...), and the error came before the
# body fit started (no "body-fit:" progress line): a wrong argument costs no fitting time.
function(expect_early_error expected_text)
  expect_run(1 "${expected_text}" ${ARGN})
  if (last_output MATCHES "body-fit:")
    message(FATAL_ERROR "clothtrack ${ARGN}: the error came after the body fit:\n${last_output}")
  endif ()
endfunction()

# read_json(OUT FILE KEYS...): the value at KEYS (names or indices) of the JSON file FILE.
function(read_json out file)
  file(READ ${file} text)
  string(JSON value GET "${text}" ${ARGN})
  set(${out} ${value} PARENT_SCOPE)
endfunction()

# expect_files(FOLDER WHAT FILES...): each of FILES (relative to FOLDER) exists; WHAT names the
# command that should have written them.
function(expect_files folder what)
  foreach (f ${ARGN})
    if (NOT EXISTS ${folder}/${f})
      message(FATAL_ERROR "${what} did not write ${f}")
    endif ()
  endforeach ()
endfunction()
