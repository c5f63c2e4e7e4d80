# Runs the clothtrack app on good and bad input and checks exit codes and messages.
# Variables: APP (the executable), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/seq ${WORK}/empty ${WORK}/bad)

include(${CMAKE_CURRENT_LIST_DIR}/expect_run.cmake)

# A small valid sequence: a tetrahedron moving up.
foreach (k 0 1 2 3)
  math(EXPR y "${k}")
  file(WRITE ${WORK}/seq/tet_${k}.obj "v 0 ${y} 0\nv 1 ${y} 0\nv 0 ${y}.5 1\nv 0 ${y} 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n")
endforeach ()

expect_run(0 "usage: clothtrack" --help)
expect_run(0 "inspect" inspect --help)
expect_run(0 "tet_3.obj" inspect ${WORK}/seq)
expect_run(0 "wrote 4 frames" convert ${WORK}/seq -o ${WORK}/out/seq.pvd --obj)
if (NOT EXISTS ${WORK}/out/seq/seq_0003.vtp OR NOT EXISTS ${WORK}/out/seq/seq_0003.obj)
  message(FATAL_ERROR "convert did not write the frames")
endif ()

expect_run(1 "unknown command" frobnicate)
expect_run(1 "no such file or folder" inspect ${WORK}/nothing)
expect_run(1 "no mesh file" inspect ${WORK}/empty)
expect_run(1 "--unit must be" inspect ${WORK}/seq --unit furlong)
expect_run(1 "unrecognised option" inspect ${WORK}/seq --bogus)
expect_run(1 "--output must end in .pvd" convert ${WORK}/seq -o ${WORK}/x.vtp)
file(WRITE ${WORK}/bad/a_0.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
file(WRITE ${WORK}/bad/a_1.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
expect_run(1 "a_1.obj:4: face index 9 out of range" inspect ${WORK}/bad)
file(WRITE ${WORK}/bad/a_1.obj "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
expect_run(1 "a_1.obj: vertex 1 has a NaN" inspect ${WORK}/bad)
file(WRITE ${WORK}/bad/a_1.obj "")
expect_run(1 "a_1.obj: empty file" convert ${WORK}/bad -o ${WORK}/bad.pvd)

# The built-in body model: written as a model file and as a shaped mesh.
expect_run(0 "40 landmarks" body-model -o ${WORK}/model.vtp --mesh ${WORK}/body.obj --beta 1.0,-0.5)
if (NOT EXISTS ${WORK}/model.vtp OR NOT EXISTS ${WORK}/body.obj)
  message(FATAL_ERROR "body-model did not write its files")
endif ()
expect_run(1 "--beta takes comma-separated numbers" body-model --mesh ${WORK}/b.obj --beta 1,x)
expect_run(1 "nothing to do" body-model)

# simulate-capture: the shaped body becomes an independently re-meshed capture with a source map.
expect_run(0 "wrote 1 captured frames" simulate-capture ${WORK}/body.obj -o ${WORK}/capture --voxel 0.02 --holes 2)
if (NOT EXISTS ${WORK}/capture/frames/frame_0000.obj OR NOT EXISTS ${WORK}/capture/source_map/frame_0000.vtp)
  message(FATAL_ERROR "simulate-capture did not write its outputs")
endif ()
expect_run(1 "--voxel must be between" simulate-capture ${WORK}/body.obj -o ${WORK}/capture --voxel 5)
expect_run(1 "no such file or folder" simulate-capture ${WORK}/none -o ${WORK}/capture)

# synth: a short dress-walk with every output.
expect_run(0 "wrote 3 frames of 'dress-walk'" synth --preset dress-walk --frames 3 --seed 7 -o ${WORK}/synth)
foreach (f frames/frame_0002.obj ground_truth/frame_0002.obj source_map/frame_0002.vtp body.json markers.csv)
  if (NOT EXISTS ${WORK}/synth/${f})
    message(FATAL_ERROR "synth did not write ${f}")
  endif ()
endforeach ()
file(STRINGS ${WORK}/synth/markers.csv marker_lines)
list(LENGTH marker_lines marker_count)
if (NOT marker_count EQUAL 43) # header + 3 frames x 14 markers
  message(FATAL_ERROR "markers.csv has ${marker_count} lines, expected 43")
endif ()
expect_run(1 "unknown preset 'kilt-jog'" synth --preset kilt-jog -o ${WORK}/synth2)

# select-template on the synthetic capture: a table and a chosen frame.
expect_run(0 "template frame:" select-template ${WORK}/synth/frames --persistence 1 --csv ${WORK}/criteria.csv)
expect_run(0 "template frame: 1 (frame_0001.obj), set by --template" select-template ${WORK}/synth/frames --template 1)
expect_run(1 "--template 7 is out of range" select-template ${WORK}/synth/frames --template 7)

# body-fit on the synthetic capture: bodies, landmarks and a summary whose figures are sane.
expect_run(0 "fitted 3 frames" body-fit ${WORK}/synth/frames -o ${WORK}/bodyfit --shape-frames 2)
foreach (f bodies.pvd bodies/bodies_0002.vtp landmarks.pvd landmarks/landmarks_0002.vtp body_fit.json)
  if (NOT EXISTS ${WORK}/bodyfit/${f})
    message(FATAL_ERROR "body-fit did not write ${f}")
  endif ()
endforeach ()
file(READ ${WORK}/bodyfit/body_fit.json summary)
string(JSON found GET "${summary}" landmarks_found_fraction)
string(JSON status GET "${summary}" per_frame 1 status)
if (found LESS 0.7 OR NOT status STREQUAL "ok")
  message(FATAL_ERROR "body-fit: landmarks found ${found}, frame 1 status ${status}")
endif ()
expect_run(1 "a_1.obj: empty file" body-fit ${WORK}/bad -o ${WORK}/bodyfit_bad)
expect_run(1 "--samples must be at least 50" body-fit ${WORK}/synth/frames -o ${WORK}/x --samples 3)
