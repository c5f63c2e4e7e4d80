# The C++ example chain (reader -> body fit -> correspondence -> template fit -> error -> writer) on
# a short synthetic capture. Variables: APP (clothtrack), EXAMPLE (the example), WORK (scratch).
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)
expect_run(0 "wrote 3 frames" synth --preset skirt-turn --frames 3 --seed 3 -o ${WORK}/synth)
execute_process(COMMAND ${EXAMPLE} ${WORK}/synth/frames ${WORK}/synth/ground_truth ${WORK}/out/aligned.pvd
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
message(STATUS "${out}")
if (NOT code EQUAL 0 OR NOT out MATCHES "wrote 3 frames" OR NOT EXISTS ${WORK}/out/aligned/aligned_0002.vtp)
  message(FATAL_ERROR "example: exit ${code}\n${out}\n${err}")
endif ()
# Every frame within a few centimetres (measured about 1 cm).
string(REGEX MATCHALL "\n +[0-9]+ +[0-9.]+ " rows "${out}")
list(LENGTH rows count)
if (NOT count EQUAL 3)
  message(FATAL_ERROR "example: expected 3 error rows\n${out}")
endif ()
foreach (row IN LISTS rows)
  string(REGEX REPLACE "^\n +[0-9]+ +([0-9.]+) $" "\\1" mean "${row}")
  if (mean GREATER 3.0)
    message(FATAL_ERROR "example: mean error ${mean} cm\n${out}")
  endif ()
endforeach ()
# A missing folder: exit 1 and the reader's message.
execute_process(COMMAND ${EXAMPLE} ${WORK}/missing ${WORK}/synth/ground_truth ${WORK}/out/x.pvd
  RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET TIMEOUT 60)
if (NOT code EQUAL 1 OR NOT err MATCHES "missing")
  message(FATAL_ERROR "example on a missing folder: exit ${code}\n${err}")
endif ()
