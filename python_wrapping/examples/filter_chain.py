#!/usr/bin/env python3
"""The ClothTrack filters chained with VTK's own, one stage at a time.

    python3 filter_chain.py FRAMES OUT.vtp

Reads a sequence, fits the body model and its landmarks, chooses the template and computes the
geodesic-patch correspondences, fits the template to every frame, then uses VTK's own
vtkCurvatures on the last aligned frame and writes it. Shows how to reach every stage's outputs.
"""
import sys

import numpy as np

from vtkmodules.util import numpy_support
from vtkmodules.vtkFiltersGeneral import vtkCurvatures
from vtkmodules.vtkFiltersExtraction import vtkExtractBlock
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import clothtrack

if len(sys.argv) != 3:
    sys.exit(__doc__)
frames_path, out_path = sys.argv[1:]

reader = clothtrack.ctMeshSequenceReader()
reader.SetFileName(frames_path)
reader.UpdateInformation()
n = reader.GetNumberOfFrames()
print("%d frames" % n)

body = clothtrack.ctBodyFit()  # output 0: fitted bodies, 1: landmarks, 2: status table
body.SetInputConnection(reader.GetOutputPort(1))
correspondence = clothtrack.ctPatchCorrespondence()  # output 0: correspondences, 1: summary table
correspondence.SetInputConnection(0, reader.GetOutputPort(1))
correspondence.SetInputConnection(1, body.GetOutputPort(1))
fit = clothtrack.ctTemplateFit()  # output 0: the aligned template per frame, 1: summary table
fit.SetInputConnection(0, reader.GetOutputPort(1))
fit.SetInputConnection(1, correspondence.GetOutputPort(0))
fit.SetInputConnection(2, body.GetOutputPort(1))
fit.SetInputConnection(3, body.GetOutputPort(0))
fit.Update()
print("template frame %d" % correspondence.GetChosenFrame())

summary = fit.GetSummaryOutput()
for k in range(summary.GetNumberOfRows()):
    print("frame %d: mean distance to the frame %.2f cm"
          % (k, 100 * summary.GetValueByName(k, "MeanSurfaceDistance").ToDouble()))

# Any VTK filter takes one aligned frame: here the last one, through vtkExtractBlock.
last = vtkExtractBlock()
last.SetInputConnection(fit.GetOutputPort(0))
last.AddIndex(n)  # flat index: 0 is the root, block k is k + 1
last.Update()
frame = last.GetOutput().GetBlock(0)
curvature = vtkCurvatures()
curvature.SetInputData(frame)
curvature.SetCurvatureTypeToMean()
curvature.Update()
mean_curvature = numpy_support.vtk_to_numpy(curvature.GetOutput().GetPointData().GetArray("Mean_Curvature"))
print("last frame: %d vertices, median |mean curvature| %.2f 1/m"
      % (frame.GetNumberOfPoints(), np.median(np.abs(mean_curvature))))
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(curvature.GetOutputPort())
writer.SetFileName(out_path)
writer.Write()
print("wrote", out_path)
