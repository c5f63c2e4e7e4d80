# Point clouds end to end: depth-camera clouds simulated from a synthetic capture, reconstructed
# ('reconstruct'), and aligned directly ('align' given clouds); bad clouds refused.
# Variables: APP (the executable), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bad)
include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

expect_run(0 "wrote 5 frames" synth --preset skirt-turn --frames 5 --seed 3 -o ${WORK}/synth)
expect_run(0 "wrote 5 captured point clouds" simulate-capture ${WORK}/synth/ground_truth
  -o ${WORK}/clouds --point-cloud --cameras 4 --noise 0.003 --outliers 0.01)
expect_run(0 "wrote 5 reconstructed frames" reconstruct ${WORK}/clouds/frames -o ${WORK}/rec)
file(READ ${WORK}/rec/reconstruction.json report)
string(JSON doubtful GET "${report}" doubtful_frames)
string(JSON pieces GET "${report}" frames 0 pieces)
string(JSON vertices GET "${report}" frames 0 vertices)
string(JSON distance GET "${report}" frames 0 mean_point_distance_m)
message(STATUS "frame 0: ${vertices} vertices, ${pieces} pieces, points ${distance} m from it")
if (NOT doubtful EQUAL 0 OR pieces GREATER 4 OR vertices LESS 3000 OR distance GREATER 0.004)
  message(FATAL_ERROR "reconstruction.json: ${doubtful} doubtful, frame 0 ${pieces} pieces, "
                      "${vertices} vertices, ${distance} m")
endif ()

# A second run reuses every mesh; other options redo them.
expect_run(0 "wrote 5 reconstructed frames" reconstruct ${WORK}/clouds/frames -o ${WORK}/rec)
file(READ ${WORK}/rec/reconstruction.json report)
string(JSON reused GET "${report}" reused_frames)
string(JSON recorded LENGTH "${report}" frames)
if (NOT reused EQUAL 5 OR NOT recorded EQUAL 5)
  message(FATAL_ERROR "second reconstruct: ${reused} frames reused, ${recorded} recorded (expected 5, 5)")
endif ()
expect_run(0 "wrote 5 reconstructed frames" reconstruct ${WORK}/clouds/frames -o ${WORK}/rec --poisson-depth 6)
file(READ ${WORK}/rec/reconstruction.json report)
string(JSON reused GET "${report}" reused_frames)
if (NOT reused EQUAL 0)
  message(FATAL_ERROR "reconstruct with another depth reused ${reused} frames")
endif ()

# align takes the clouds as they are: reconstructed into OUT/reconstructed first.
expect_run(0 "aligned 5 frames" align ${WORK}/clouds/frames --ground-truth ${WORK}/synth/ground_truth
  -o ${WORK}/out --no-report)
if (NOT EXISTS ${WORK}/out/reconstructed/frames/frame_0004.obj)
  message(FATAL_ERROR "align did not reconstruct the clouds into out/reconstructed")
endif ()
file(READ ${WORK}/out/metrics.json metrics)
string(JSON mean GET "${metrics}" mean_vertex_error_m)
string(JSON within10 GET "${metrics}" within_10cm)
message(STATUS "aligned from clouds: mean error ${mean} m, within 10 cm ${within10}")
if (mean GREATER 0.04 OR within10 LESS 0.95)
  message(FATAL_ERROR "metrics.json: mean error ${mean} m, within 10 cm ${within10}")
endif ()

# Bad clouds: each refused with one line naming the file and the problem.
file(WRITE ${WORK}/bad/empty.pcd "")
expect_run(1 "empty.pcd: empty file" reconstruct ${WORK}/bad/empty.pcd -o ${WORK}/bad/out)
file(WRITE ${WORK}/bad/nan.xyz "nan nan nan\nnan nan nan\n")
expect_run(1 "nan.xyz: no point of the cloud has finite coordinates" reconstruct ${WORK}/bad/nan.xyz
  -o ${WORK}/bad/out --unit m --up y)
file(WRITE ${WORK}/bad/few.xyz "0 0 0\n0 1 0\n0 0 1\n1.7 0 0\n")
expect_run(1 "few.xyz: the point cloud has 4 valid points, too few" reconstruct ${WORK}/bad/few.xyz
  -o ${WORK}/bad/out)
# Points filling a box (all outliers): no surface.
set(lines "")
foreach (i RANGE 0 2999)
  math(EXPR x "(${i} * 7919) % 1000")
  math(EXPR y "(${i} * 104729) % 1700")
  math(EXPR z "(${i} * 1299709) % 1000")
  string(APPEND lines "0.${x} 1.${y} 0.${z}\n")
endforeach ()
file(WRITE ${WORK}/bad/noise.xyz "${lines}")
expect_run(1 "noise.xyz: the points do not lie on a surface" reconstruct ${WORK}/bad/noise.xyz
  -o ${WORK}/bad/out)
# A mesh among clouds.
file(COPY ${WORK}/synth/frames/frame_0000.obj DESTINATION ${WORK}/bad/mixed)
file(COPY ${WORK}/clouds/frames/frame_0001.pcd DESTINATION ${WORK}/bad/mixed)
expect_run(1 "frame_0000.obj: not a point cloud" reconstruct ${WORK}/bad/mixed -o ${WORK}/bad/out)
# Options out of range.
expect_run(1 "--cameras must be between 1 and 64" simulate-capture ${WORK}/synth/ground_truth
  -o ${WORK}/bad/sim --point-cloud --cameras 0)
expect_run(1 "--cloud-format must be pcd, ply or xyz" simulate-capture ${WORK}/synth/ground_truth
  -o ${WORK}/bad/sim --point-cloud --cloud-format las)
expect_run(1 "--poisson-depth must be between 5 and 12" reconstruct ${WORK}/clouds/frames
  -o ${WORK}/bad/out --poisson-depth 20)
