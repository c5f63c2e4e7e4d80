#!/usr/bin/env python3
"""Render meshes side by side from the front-left, e.g. a ground-truth frame next to its capture.

usage: PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 scripts/render_side_by_side.py \
           OUT.png MESH [MESH ...]
"""
import sys

import clothtrack
from clothtrack.rendering import colour_actor, offscreen_window, save_png
from vtkmodules.vtkRenderingCore import vtkRenderer

out, meshes = sys.argv[1], sys.argv[2:]
window = offscreen_window(420 * len(meshes), 640)
colours = [(0.55, 0.75, 0.55), (0.85, 0.85, 0.85), (0.86, 0.72, 0.62), (0.6, 0.7, 0.9)]
for index, path in enumerate(meshes):
    frame = clothtrack.read_sequence(path)[0]
    actor = colour_actor(frame, colours[index % len(colours)], smooth_normals=True)
    renderer = vtkRenderer()
    renderer.SetViewport(index / len(meshes), 0, (index + 1) / len(meshes), 1)
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor)
    bounds = frame.GetBounds()
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0] + 1.6, centre[1] + 0.6, centre[2] + 3.2)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    window.AddRenderer(renderer)
save_png(window, out)
print("wrote", out)
