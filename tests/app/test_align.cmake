# clothtrack align end to end on a short synthetic capture with ground truth: the aligned
# sequence and metrics.json, a resumed run, and bad input.
# Variables: APP (the executable), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/empty ${WORK}/bad)
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

function(read_metric out)
  file(READ ${WORK}/out/metrics.json metrics)
  string(JSON value GET "${metrics}" ${ARGN})
  set(${out} ${value} PARENT_SCOPE)
endfunction()

expect_run(0 "wrote 6 frames" synth --preset skirt-turn --frames 6 --seed 3 --voxel 0.02
  -o ${WORK}/synth)
expect_run(0 "aligned 6 frames" align ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth
  --markers ${WORK}/synth/markers.csv -o ${WORK}/out)
expect_files(${WORK}/out "align"
  aligned.pvd aligned/aligned_0000.vtp aligned/aligned_0005.vtp metrics.json work/landmarks.jsonl
  body_fit.json report.html images/per_frame_error.png images/cumulative_error.png
  images/confidence.png)
file(GLOB correspondence_images ${WORK}/out/images/correspondence_*.png)
if (NOT correspondence_images)
  message(FATAL_ERROR "the report has no correspondence image")
endif ()
# The report says how many frames are doubtful (this accurate result: none).
file(STRINGS ${WORK}/out/report.html doubtful_line REGEX "0 of 6 frames are doubtful")
if (NOT doubtful_line)
  message(FATAL_ERROR "the report does not say that none of the 6 frames is doubtful")
endif ()
file(GLOB body_images ${WORK}/out/images/body_*.png)
list(LENGTH body_images body_image_count)
file(STRINGS ${WORK}/out/report.html body_links REGEX "images/body_")
if (body_image_count LESS 3 OR NOT body_links)
  message(FATAL_ERROR "the report shows ${body_image_count} fitted-body images")
endif ()
# Without a display the report starts a virtual one; with no Xvfb either it says what to install.
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY PATH=${WORK}/empty ${APP} report ${WORK}/out
  RESULT_VARIABLE code ERROR_VARIABLE err)
if (NOT code EQUAL 1 OR NOT err MATCHES "^clothtrack report: renders need an X display or Xvfb")
  message(FATAL_ERROR "report without display and Xvfb: exit ${code}\n${err}")
endif ()
# The template was chosen by pose: the frame whose fitted body is nearest the rest pose.
read_metric(criterion template_criterion)
if (NOT criterion STREQUAL "rest-pose")
  message(FATAL_ERROR "metrics.json: template_criterion ${criterion}")
endif ()
read_metric(frames frames)
read_metric(template template_frame)
read_metric(mean mean_vertex_error_m)
read_metric(within10 within_10cm)
read_metric(rss peak_rss_mb)
read_metric(fit_seconds stage_seconds fit)
read_metric(marker_mean marker_mean_error_m)
read_metric(knee per_marker_mean_error_m left_knee)
# Markers are on the body, under the skirt at the knees: a few centimetres (measured 0.8 cm mean).
if (marker_mean GREATER 0.04 OR NOT marker_mean GREATER 0 OR NOT knee GREATER 0)
  message(FATAL_ERROR "metrics.json: marker error ${marker_mean} m, left knee ${knee} m")
endif ()
file(READ ${WORK}/out/metrics.json metrics)
string(JSON per_frame_count LENGTH "${metrics}" per_frame_mean_error_m)
message(STATUS "template ${template}, mean error ${mean} m, within 10 cm ${within10}, peak ${rss} MB")
if (NOT frames EQUAL 6 OR NOT per_frame_count EQUAL 6 OR template LESS 0 OR template GREATER 5)
  message(FATAL_ERROR "metrics.json: frames ${frames}, per-frame errors ${per_frame_count}, template ${template}")
endif ()
# A short, slow motion: the template tracks it to a few centimetres.
if (mean GREATER 0.04 OR within10 LESS 0.95 OR NOT rss GREATER 10 OR NOT fit_seconds GREATER 0)
  message(FATAL_ERROR "metrics.json: mean error ${mean} m, within 10 cm ${within10}, rss ${rss}, fit ${fit_seconds} s")
endif ()

# Every frame is judged without the truth; this accurate result has no doubtful frame.
string(JSON confidence_count LENGTH "${metrics}" per_frame_confidence)
string(JSON doubtful_count LENGTH "${metrics}" doubtful_frames)
string(JSON attempts_count LENGTH "${metrics}" per_frame_fit_attempts)
string(JSON body_count LENGTH "${metrics}" per_frame_body_distance_m)
read_metric(confidence0 per_frame_confidence 0)
read_metric(template_body per_frame_body_distance_m ${template})
if (NOT confidence_count EQUAL 6 OR NOT attempts_count EQUAL 6 OR NOT doubtful_count EQUAL 0
    OR NOT confidence0 EQUAL 1 OR NOT body_count EQUAL 6 OR template_body STREQUAL "null"
    OR template_body GREATER 1e-6)
  message(FATAL_ERROR "metrics.json: ${confidence_count} confidences (frame 0: ${confidence0}), "
                      "${doubtful_count} doubtful frames, ${body_count} body distances (template "
                      "frame: ${template_body})")
endif ()

# eval recomputes the errors of the folder from its aligned frames: the same figures.
expect_run(0 "evaluated 6 frames" eval ${WORK}/out --ground-truth ${WORK}/synth/ground_truth
  --markers ${WORK}/synth/markers.csv)
read_metric(eval_mean mean_vertex_error_m)
read_metric(eval_marker marker_mean_error_m)
if (NOT eval_mean STREQUAL mean OR NOT eval_marker STREQUAL marker_mean)
  message(FATAL_ERROR "eval: mean ${eval_mean} (align ${mean}), markers ${eval_marker} (align ${marker_mean})")
endif ()
expect_run(1 "eval needs --ground-truth" eval ${WORK}/out)
expect_run(1 "no metrics.json" eval ${WORK}/empty --ground-truth ${WORK}/synth/ground_truth)

# Frames 0 and 5 lost (as if the run had been stopped): a second run fits only those.
# A write cut short leaves a .part file: removed, and said, at the start of the next run.
file(REMOVE ${WORK}/out/aligned/aligned_0000.vtp ${WORK}/out/aligned/aligned_0005.vtp ${WORK}/out/metrics.json)
file(WRITE ${WORK}/out/aligned/aligned_0005.vtp.part "<VTKFile")
expect_run(0 "removed 1 partial files left by an interrupted run" align ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth -o ${WORK}/out --no-report)
if (EXISTS ${WORK}/out/aligned/aligned_0005.vtp.part)
  message(FATAL_ERROR "the leftover .part file is still there")
endif ()
file(REMOVE ${WORK}/out/aligned/aligned_0000.vtp ${WORK}/out/aligned/aligned_0005.vtp ${WORK}/out/metrics.json)
expect_run(0 "4 resumed" align ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth -o ${WORK}/out --no-report)
read_metric(resumed resumed_frames)
read_metric(mean_again mean_vertex_error_m)
read_metric(reused_targets reused_correspondence_frames)
# (The correspondences of both lost frames are still in the work folder, unless one is the template.)
if (NOT resumed EQUAL 4 OR reused_targets LESS 1)
  message(FATAL_ERROR "resumed ${resumed} frames (expected 4), reused the correspondences of ${reused_targets} (expected 1 or 2)")
endif ()
if (mean_again GREATER 0.04 OR NOT EXISTS ${WORK}/out/aligned/aligned_0005.vtp)
  message(FATAL_ERROR "resumed run: mean error ${mean_again} m")
endif ()
# Another fit option with the same work folder: landmarks and correspondences are reused, the fit
# is not.
expect_run(0 "reused" align ${WORK}/synth/frames --ground-truth ${WORK}/synth/ground_truth -o ${WORK}/lbfgs
  --work ${WORK}/out/work --solver lbfgs --no-report)
read_metric(lbfgs_mean mean_vertex_error_m)
file(READ ${WORK}/lbfgs/metrics.json lbfgs_metrics)
string(JSON lbfgs_correspond GET "${lbfgs_metrics}" stage_seconds correspond)
string(JSON lbfgs_resumed GET "${lbfgs_metrics}" resumed_frames)
if (lbfgs_correspond GREATER 0.5 OR NOT lbfgs_resumed EQUAL 0 OR lbfgs_mean GREATER 0.05)
  message(FATAL_ERROR "shared work folder: correspondence ${lbfgs_correspond} s, resumed ${lbfgs_resumed}, error ${lbfgs_mean}")
endif ()
# The stages alone: correspond, then fit from the same work folder, then a movie.
expect_run(0 "landmarks and correspondences of 3 frames" correspond ${WORK}/synth/frames --frames 0:3
  -o ${WORK}/staged)
expect_run(0 "body fit: landmarks of 3 frames reused" fit ${WORK}/synth/frames --frames 0:3 -o ${WORK}/staged
  --ground-truth ${WORK}/synth/ground_truth --no-report)
file(READ ${WORK}/staged/metrics.json staged_metrics)
string(JSON staged_mean GET "${staged_metrics}" mean_vertex_error_m)
string(JSON staged_correspond GET "${staged_metrics}" stage_seconds correspond)
if (staged_mean GREATER 0.04 OR staged_correspond GREATER 0.5)
  message(FATAL_ERROR "fit after correspond: error ${staged_mean}, correspondence ${staged_correspond} s")
endif ()
expect_early_error("run 'clothtrack correspond'" fit ${WORK}/synth/frames --frames 2:5 -o ${WORK}/unstaged)
# A model file rewritten in place is another model: the stored body fits are not reused.
expect_run(0 "40 landmarks" body-model -o ${WORK}/model.vtp)
expect_run(0 "landmarks and correspondences of 2 frames" correspond ${WORK}/synth/frames --frames 0:2
  -o ${WORK}/staged_model --model ${WORK}/model.vtp)
expect_run(0 "body fit: landmarks of 2 frames reused" fit ${WORK}/synth/frames --frames 0:2
  -o ${WORK}/staged_model --model ${WORK}/model.vtp --no-report)
expect_run(0 "40 landmarks" body-model -o ${WORK}/model.vtp --spread headSize=2)
expect_early_error("run 'clothtrack correspond'" fit ${WORK}/synth/frames --frames 0:2
  -o ${WORK}/staged_model --model ${WORK}/model.vtp)
expect_run(0 "wrote 3 frames" render ${WORK}/staged --movie-only --size 320x320)
if (NOT EXISTS ${WORK}/staged/movie/movie_0002.png)
  message(FATAL_ERROR "render wrote no movie frames")
endif ()
# The ablation without Ec, prediction and body start needs no body fit when the template is not
# chosen by pose.
expect_run(0 "body fit: skipped" align ${WORK}/synth/frames --frames 0:3 -o ${WORK}/icp --no-correspondence
  --predict-radius 0 --no-body-start --template-criterion area-ratio --no-report)
file(WRITE ${WORK}/bad/markers.csv "frame,time,marker,x,y,z\n0,0,knee,1,2\n")
expect_run(1 "markers.csv:2: expected frame,time,marker,x,y,z" align ${WORK}/synth/frames -o ${WORK}/x
  --markers ${WORK}/bad/markers.csv)
# Other options: earlier results are not reused.
expect_run(0 "replaced" align ${WORK}/synth/frames --frames 1:4 -o ${WORK}/out --no-report)
read_metric(frames frames)
if (NOT frames EQUAL 3)
  message(FATAL_ERROR "--frames 1:4 aligned ${frames} frames")
endif ()

# A corrupt frame is an error by default; --skip-bad-frames leaves it out with a warning, and a gap
# in the numbering is reported.
file(MAKE_DIRECTORY ${WORK}/gappy)
foreach (k 0 1 4)
  file(COPY ${WORK}/synth/frames/frame_000${k}.obj DESTINATION ${WORK}/gappy)
endforeach ()
file(WRITE ${WORK}/gappy/frame_0002.obj "v 0 0 0\nv 1 0 0\nf 1 2 7\n")
expect_run(1 "frame_0002.obj:3: face index 7 out of range" align ${WORK}/gappy -o ${WORK}/gappy_out)
expect_run(0 "frame left out" align ${WORK}/gappy -o ${WORK}/gappy_out --skip-bad-frames --no-report)
expect_run(0 "frames 2 to 3 are missing" align ${WORK}/gappy -o ${WORK}/gappy_out --skip-bad-frames --no-report)
# A list in another order is a chosen set of poses, not a numbered sequence: no gap is reported.
file(WRITE ${WORK}/poses.txt "${WORK}/gappy/frame_0004.obj\n${WORK}/gappy/frame_0000.obj\n${WORK}/gappy/frame_0001.obj\n")
execute_process(COMMAND ${APP} align ${WORK}/poses.txt -o ${WORK}/poses_out --no-report
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if (NOT code EQUAL 0 OR err MATCHES "are missing" OR NOT "${out}${err}" MATCHES "aligned 3 frames")
  message(FATAL_ERROR "align on a list of poses: exit ${code}\nstdout: ${out}\nstderr: ${err}")
endif ()

expect_run(0 "--ground-truth" align --help)
expect_run(1 "no metrics.json" report ${WORK}/empty)
expect_run(1 "no such file or folder" align ${WORK}/nothing -o ${WORK}/x)
expect_run(1 "no mesh file" align ${WORK}/empty -o ${WORK}/x)
expect_run(1 "--frames must be A:B" align ${WORK}/synth/frames --frames 3 -o ${WORK}/x)
expect_run(1 "selects no frame" align ${WORK}/synth/frames --frames 4:2 -o ${WORK}/x)
expect_run(1 "--solver-tolerance and --intermediate-tolerance must be in (0, 1)" align ${WORK}/synth/frames -o ${WORK}/x --intermediate-tolerance 0)
expect_run(1 "--refactor-steps must be 0 or more" align ${WORK}/synth/frames -o ${WORK}/x --refactor-steps -1)
expect_run(1 "--nearest-reuse must be 0 or more" align ${WORK}/synth/frames -o ${WORK}/x --nearest-reuse -0.001)
expect_run(1 "--minimum-seed-consensus must be between 0 and 1" align ${WORK}/synth/frames -o ${WORK}/x --seed-consensus 1.5)
expect_run(1 "--factor-backend must be block or cholmod" align ${WORK}/synth/frames -o ${WORK}/x --factor-backend dense)
expect_run(1 "--persistence must be at least 1" align ${WORK}/synth/frames -o ${WORK}/x --persistence 0)
# Aligned frames are written in the background: a failed write still ends the run with its error.
# (A run with the same options first, so that the second resumes in the folder as it is.)
set(blocked_run fit ${WORK}/synth/frames --frames 0:3 --work ${WORK}/staged/work -o ${WORK}/blocked
  --no-report)
expect_run(0 "aligned 3 frames" ${blocked_run})
file(REMOVE_RECURSE ${WORK}/blocked/aligned)
file(WRITE ${WORK}/blocked/aligned "a file where the aligned frames' folder should be")
expect_run(1 "blocked/aligned: cannot create folder" ${blocked_run})
expect_run(1 "--solver must be" align ${WORK}/synth/frames --solver magic -o ${WORK}/x)
expect_early_error("is out of range" align ${WORK}/synth/frames --template 9 -o ${WORK}/no_such_template)
expect_run(1 "at least two readable frames" align ${WORK}/synth/frames --frames 2:3 -o ${WORK}/x)
expect_run(1 "the option '--output' is required" align ${WORK}/synth/frames)
file(WRITE ${WORK}/bad/a_0.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
file(WRITE ${WORK}/bad/a_1.obj "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
expect_run(1 "a_1.obj: vertex 1 has a NaN" align ${WORK}/bad -o ${WORK}/x)
file(WRITE ${WORK}/bad/a_1.obj "")
expect_run(1 "a_1.obj: empty file" align ${WORK}/bad -o ${WORK}/x)
expect_run(1 "ground-truth frames for" align ${WORK}/synth/frames --ground-truth ${WORK}/bad -o ${WORK}/x)

# Frames and ground truth at another scale: a frame in millimetres is refused, or left out with
# --skip-bad-frames; so is a ground truth in centimetres; a frame that is no person is named.
file(MAKE_DIRECTORY ${WORK}/units)
foreach (k 0 1 3)
  file(COPY ${WORK}/synth/frames/frame_000${k}.obj DESTINATION ${WORK}/units)
endforeach ()
expect_run(0 "wrote 1 frames" convert ${WORK}/synth/frames/frame_0002.obj -o ${WORK}/mm.pvd --obj --scale 1000)
file(RENAME ${WORK}/mm/mm_0000.obj ${WORK}/units/frame_0002.obj)
expect_run(1 "units/frame_0002.obj: its surface is" align ${WORK}/units -o ${WORK}/x)
expect_run(1 "(a unit 1000 times smaller?): convert it, or leave it out with --skip-bad-frames"
  align ${WORK}/units -o ${WORK}/x)
set(surface_only --no-correspondence --predict-radius 0 --no-body-start --template-criterion area-ratio --no-report)
expect_run(0 "(frame left out)" align ${WORK}/units -o ${WORK}/units_out --skip-bad-frames ${surface_only})
file(READ ${WORK}/units_out/metrics.json units_metrics)
string(JSON kept_frames GET "${units_metrics}" frames)
string(JSON kept_numbers GET "${units_metrics}" frame_numbers)
string(REGEX REPLACE "[ \n]" "" kept_numbers "${kept_numbers}")
if (NOT kept_frames EQUAL 3 OR NOT kept_numbers STREQUAL "[0,1,3]")
  message(FATAL_ERROR "--skip-bad-frames kept ${kept_frames} frames, numbers ${kept_numbers}")
endif ()
expect_run(0 "wrote 6 frames" convert ${WORK}/synth/ground_truth -o ${WORK}/truth_cm.pvd --obj --scale 100)
file(REMOVE_RECURSE ${WORK}/truth_cm_obj)
file(GLOB truth_cm_files ${WORK}/truth_cm/*.obj)
file(COPY ${truth_cm_files} DESTINATION ${WORK}/truth_cm_obj)
expect_run(1 "the ground truth's surface is" align ${WORK}/synth/frames --ground-truth ${WORK}/truth_cm_obj -o ${WORK}/x)
expect_run(1 "(a unit 100 times smaller?); it is read with the input's --unit" align ${WORK}/synth/frames
  --ground-truth ${WORK}/truth_cm_obj -o ${WORK}/x)
# A 60 cm box where the person stood: the body model does not fit it, and the warning says so.
file(MAKE_DIRECTORY ${WORK}/box)
foreach (k 0 1 3)
  file(COPY ${WORK}/synth/frames/frame_000${k}.obj DESTINATION ${WORK}/box)
endforeach ()
set(box "")
foreach (x -0.3 0.3)
  foreach (y 0.6 1.2)
    foreach (z -0.3 0.3)
      string(APPEND box "v ${x} ${y} ${z}\n")
    endforeach ()
  endforeach ()
endforeach ()
string(APPEND box "f 1 2 4\nf 1 4 3\nf 5 7 8\nf 5 8 6\nf 1 5 6\nf 1 6 2\nf 3 4 8\nf 3 8 7\n"
  "f 1 3 7\nf 1 7 5\nf 2 6 8\nf 2 8 4\n")
file(WRITE ${WORK}/box/frame_0002.obj "${box}")
expect_run(0 "box/frame_0002.obj: the body model does not fit this frame" body-fit ${WORK}/box -o ${WORK}/box_out)
message(STATUS "align test passed")
