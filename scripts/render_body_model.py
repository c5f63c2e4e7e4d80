#!/usr/bin/env python3
"""Render the built-in body model for a few shapes and a pose, with its oriented landmarks.

usage: PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 scripts/render_body_model.py OUT.png [MODEL.vtp]

Without MODEL.vtp the built-in model is drawn.
"""
import random
import sys

import clothtrack
from clothtrack.rendering import colour_actor, offscreen_window, save_png
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkGlyph3D, vtkPolyDataNormals
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
import vtkmodules.vtkRenderingFreeType  # noqa: F401

out = sys.argv[1] if len(sys.argv) > 1 else "body_model.png"
model_file = sys.argv[2] if len(sys.argv) > 2 else ""
rng = random.Random(4)
window = offscreen_window(1500, 560)
renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
window.AddRenderer(renderer)

shapes = [[0.0] * 10] + [[rng.gauss(0, 1) for _ in range(10)] for _ in range(3)] + [[0.0] * 10]
for index, beta in enumerate(shapes):
    body = clothtrack.ctBodyModelSource()
    body.SetModelFileName(model_file)
    for k, b in enumerate(beta):
        body.SetShapeCoefficient(k, b)
    body.SetTranslation(1.0 * index, 0, 0)
    if index == len(shapes) - 1:  # a walking pose
        body.SetJointRotation(14, -0.5, 0, 0)   # left hip forward
        body.SetJointRotation(15, 0.7, 0, 0)    # left knee
        body.SetJointRotation(18, 0.35, 0, 0)   # right hip back
        body.SetJointRotation(7, 0, 0, -0.5)    # left shoulder down
        body.SetJointRotation(8, 0, -1.0, 0)    # left elbow
        body.SetJointRotation(11, 0, 0, 0.9)    # right shoulder down
    body.Update()
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(body.GetOutputPort(0))
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.86, 0.72, 0.62)
    renderer.AddActor(actor)
    # Landmarks: blue spheres with black direction arrows.
    for source, scale, colour in ((vtkSphereSource(), 0.018, (0.1, 0.3, 0.9)), (vtkArrowSource(), 0.05, (0, 0, 0))):
        glyph = vtkGlyph3D()
        glyph.SetInputConnection(body.GetOutputPort(1))
        glyph.SetSourceConnection(source.GetOutputPort())
        glyph.SetVectorModeToUseVector()
        glyph.SetScaleModeToDataScalingOff()
        glyph.SetScaleFactor(scale)
        renderer.AddActor(colour_actor(glyph.GetOutputPort(), colour))

camera = renderer.GetActiveCamera()
camera.SetFocalPoint(2.0, 0.9, 0)
camera.SetPosition(2.0 + 1.2, 1.3, 6.5)
camera.SetViewUp(0, 1, 0)
renderer.ResetCamera()
camera.Zoom(1.9)
save_png(window, out)
print("wrote", out)
