# clothtrack align under several template frames (--template-candidates): each further
# candidate's alignment in OUT/templates/, one kept in OUT by its ground-truth-free figures, and
# the choice in metrics.json. A sequence is aligned under one template unless asked.
# Variables: APP (the executable), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "wrote 4 frames" synth --preset shirt-armraise --frames 4 --seed 3 --voxel 0.025 -o ${WORK}/synth)
set(input ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth)
expect_early_error("--template-candidates must be 0 or more" align ${input} -o ${WORK}/bad
  --template-candidates -1)

# A sequence: one template, no choice.
expect_run(0 "aligned 4 frames" align ${input} -o ${WORK}/one --no-report)
file(READ ${WORK}/one/metrics.json one_text)
string(JSON one_choice ERROR_VARIABLE missing GET "${one_text}" template_choice)
string(JSON by_pose_count LENGTH "${one_text}" template_frames_by_pose)
if (NOT missing OR EXISTS ${WORK}/one/templates OR by_pose_count LESS 2)
  message(FATAL_ERROR "a sequence was aligned under several templates, or its frames by pose "
    "are missing (${by_pose_count})")
endif ()

expect_run(0 "kept the alignment under template frame" align ${input} -o ${WORK}/out
  --template-candidates 2)
set(metrics ${WORK}/out/metrics.json)
file(READ ${metrics} text)
string(JSON count LENGTH "${text}" template_choice candidates)
read_json(kept ${metrics} template_choice kept)
read_json(kept_frame ${metrics} template_choice kept_template_frame)
read_json(template ${metrics} template_frame)
read_json(first ${metrics} template_choice candidates 0 template_frame)
read_json(second ${metrics} template_choice candidates 1 template_frame)
read_json(by_pose0 ${WORK}/one/metrics.json template_frames_by_pose 0)
read_json(by_pose1 ${WORK}/one/metrics.json template_frames_by_pose 1)
read_json(chosen ${WORK}/one/metrics.json template_frame)
read_json(mean ${metrics} mean_vertex_error_m)
read_json(kept_mean ${metrics} template_choice candidates ${kept} mean_vertex_error_m)
read_json(criterion ${metrics} template_criterion)
if (NOT count EQUAL 2 OR NOT kept_frame EQUAL template OR NOT first EQUAL chosen
    OR NOT criterion STREQUAL "alignment-figures")
  message(FATAL_ERROR "metrics.json: ${count} candidates, kept frame ${kept_frame}, template "
    "${template}, first candidate ${first} (the automatic choice: ${chosen})")
endif ()
# The second candidate is the next frame by pose after the chosen one.
if (chosen EQUAL by_pose0)
  set(next ${by_pose1})
else ()
  set(next ${by_pose0})
endif ()
if (NOT second EQUAL next OR NOT EXISTS ${WORK}/out/templates/frame_${second}/metrics.json)
  message(FATAL_ERROR "the second candidate is frame ${second}, not ${next}, or has no metrics")
endif ()
if (NOT mean STREQUAL kept_mean OR mean GREATER 0.04)
  message(FATAL_ERROR "metrics.json: mean error ${mean}, the kept candidate's ${kept_mean}")
endif ()
# The kept alignment is in OUT, with the report.
expect_files(${WORK}/out "align with two templates"
  aligned.pvd aligned/aligned_0003.vtp body_fit.json report.html)
if (kept EQUAL 1 AND EXISTS ${WORK}/out/templates/frame_${second}/aligned.pvd)
  message(FATAL_ERROR "the kept alignment was not moved out of templates/frame_${second}")
endif ()
# Each candidate's folder as listed holds its own alignment: the kept one in OUT, a first one
# not kept in its own candidate folder.
foreach (i 0 1)
  read_json(folder ${metrics} template_choice candidates ${i} folder)
  read_json(frame ${metrics} template_choice candidates ${i} template_frame)
  read_json(listed_mean ${metrics} template_choice candidates ${i} mean_vertex_error_m)
  read_json(folder_mean ${WORK}/out/${folder}/metrics.json mean_vertex_error_m)
  read_json(folder_frame ${WORK}/out/${folder}/metrics.json template_frame)
  if (NOT EXISTS ${WORK}/out/${folder}/aligned.pvd OR NOT folder_frame EQUAL frame
      OR NOT folder_mean STREQUAL listed_mean OR (i EQUAL kept AND NOT folder STREQUAL "."))
    message(FATAL_ERROR "candidate ${i} (frame ${frame}) is listed in '${folder}', which holds "
      "frame ${folder_frame}'s alignment (${folder_mean} against ${listed_mean})")
  endif ()
endforeach ()
file(STRINGS ${WORK}/out/report.html kept_line REGEX "Aligned under 2 template frames; kept: frame ${kept_frame}")
if (NOT kept_line)
  message(FATAL_ERROR "the report does not show the template choice")
endif ()
