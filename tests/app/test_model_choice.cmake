# clothtrack align under two body models (--model given twice): each model's alignment in
# OUT/models/, one kept in OUT by its ground-truth-free figures, and the choice in metrics.json.
# Variables: APP (the executable), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "wrote 3 frames" synth --preset skirt-turn --frames 3 --seed 3 --voxel 0.025 -o ${WORK}/synth)
# The built-in model written to a file: a second model as good as the first.
expect_run(0 "wrote" body-model -o ${WORK}/copy.vtp)
set(input ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth)

expect_early_error("missing.vtp: no such body model file" align ${input} -o ${WORK}/bad
  --model builtin --model ${WORK}/missing.vtp)
expect_early_error("several --model values need the whole 'clothtrack align'" correspond ${input}
  -o ${WORK}/bad --model builtin --model ${WORK}/copy.vtp)

expect_run(0 "kept the alignment under model builtin" align ${input} -o ${WORK}/out
  --model builtin --model ${WORK}/copy.vtp --no-report)
expect_files(${WORK}/out "align with two models"
  aligned.pvd aligned/aligned_0002.vtp body_fit.json metrics.json
  models/0_builtin/metrics.json models/1_copy/metrics.json models/1_copy/aligned.pvd)
if (EXISTS ${WORK}/out/models/0_builtin/aligned.pvd)
  message(FATAL_ERROR "the kept alignment was not moved out of models/0_builtin")
endif ()

set(metrics ${WORK}/out/metrics.json)
read_json(kept ${metrics} model_choice kept)
file(READ ${metrics} metrics_text)
string(JSON count LENGTH "${metrics_text}" model_choice models)
read_json(model ${metrics} model)
read_json(mean ${metrics} mean_vertex_error_m)
read_json(stretch0 ${metrics} model_choice models 0 mean_stretch)
read_json(stretch1 ${metrics} model_choice models 1 mean_stretch)
read_json(surface0 ${metrics} model_choice models 0 mean_surface_distance_m)
read_json(mean0 ${metrics} model_choice models 0 mean_vertex_error_m)
read_json(other ${WORK}/out/models/1_copy/metrics.json mean_vertex_error_m)
read_json(mean1 ${metrics} model_choice models 1 mean_vertex_error_m)
# Two models that are one: neither is better, so the first named is kept.
if (NOT count EQUAL 2 OR NOT kept EQUAL 0 OR NOT model STREQUAL "builtin")
  message(FATAL_ERROR "metrics.json: ${count} models, kept ${kept} (${model}), stretches ${stretch0} and ${stretch1}")
endif ()
if (NOT stretch0 GREATER 0 OR NOT stretch1 GREATER 0 OR NOT surface0 GREATER 0 OR surface0 GREATER 0.01)
  message(FATAL_ERROR "metrics.json: mean stretches ${stretch0} and ${stretch1}, surface distance ${surface0} m")
endif ()
# The kept alignment's figures are OUT's, the other model's are its folder's.
if (NOT mean STREQUAL mean0 OR NOT mean1 STREQUAL other OR mean GREATER 0.03)
  message(FATAL_ERROR "metrics.json: mean error ${mean}, kept model's ${mean0}; other ${mean1} against ${other}")
endif ()
# The report says which model was kept, and lists both.
expect_run(0 "report.html" report ${WORK}/out)
file(STRINGS ${WORK}/out/report.html kept_line REGEX "Aligned under 2 body models; kept: builtin")
file(STRINGS ${WORK}/out/report.html copy_row REGEX "copy.vtp</th><td>mean stretch")
if (NOT kept_line OR NOT copy_row)
  message(FATAL_ERROR "the report does not show the model choice")
endif ()
