#!/usr/bin/env python3
"""Colour-coded dense correspondence: a smooth colour field on the template (left) carried to
other frames by ctPatchCorrespondence. A frame vertex takes the colour of the template vertex
mapped nearest to it (within 3 cm); grey means nothing was mapped there.

usage: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 python_wrapping/clothtrack/virtual_display.py \\
           -- /usr/bin/python3 scripts/render_correspondence.py OUT.png SEQUENCE [STRIDE [SHOWN ...]]
(virtual_display only without an X display).
SEQUENCE is anything the sequence reader opens (a folder of frames). Every STRIDE-th frame
(default 5) is fitted and matched; SHOWN are indices among those frames to draw (default: three
spread over the sequence). Prints the template frame and each frame's matched fraction.
"""
import sys

import numpy as np
import clothtrack
from clothtrack.rendering import colour_field_actor, offscreen_window, save_png
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData, vtkPointLocator
from vtkmodules.vtkRenderingCore import vtkRenderer

GREY = (170, 170, 170)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, path = sys.argv[1], sys.argv[2]
    stride = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    frames = clothtrack.read_sequence(path)[::stride]
    sequence = vtkMultiBlockDataSet()
    for k, frame in enumerate(frames):
        sequence.SetBlock(k, frame)
    body = clothtrack.ctBodyFit()
    body.SetInputData(sequence)
    correspondence = clothtrack.ctPatchCorrespondence()
    correspondence.SetInputData(0, sequence)
    correspondence.SetInputConnection(1, body.GetOutputPort(1))
    correspondence.Update()
    template = correspondence.GetChosenFrame()
    result = correspondence.GetOutputDataObject(0)
    print("template frame", template * stride, "(every %d-th frame)" % stride)
    shown = [int(s) for s in sys.argv[4:]] or [len(frames) // 4, len(frames) // 2,
                                               3 * len(frames) // 4]

    # Smooth colour field on the template: normalised coordinates as RGB.
    points = numpy_support.vtk_to_numpy(frames[template].GetPoints().GetData())
    low, high = points.min(axis=0), points.max(axis=0)
    template_rgb = (40 + 215 * (points - low) / np.maximum(high - low, 1e-9)).astype(np.uint8)

    columns = 1 + len(shown)
    window = offscreen_window(360 * columns, 620)
    meshes = [(frames[template], template_rgb)]
    for k in shown:
        block = result.GetBlock(k)
        matched = numpy_support.vtk_to_numpy(block.GetPointData().GetArray("Matched")) > 0
        targets = numpy_support.vtk_to_numpy(block.GetPointData().GetArray("TargetPosition"))
        print("frame %d: matched %.1f %%" % (k * stride, 100 * matched.mean()))
        mapped = vtkPoints()
        mapped.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(targets[matched]), deep=1))
        cloud = vtkPolyData()
        cloud.SetPoints(mapped)
        locator = vtkPointLocator()
        locator.SetDataSet(cloud)
        locator.BuildLocator()
        colours = template_rgb[matched]
        frame_points = numpy_support.vtk_to_numpy(frames[k].GetPoints().GetData())
        rgb = np.empty((len(frame_points), 3), dtype=np.uint8)
        for i, p in enumerate(frame_points):
            j = locator.FindClosestPoint(p)
            near = j >= 0 and np.linalg.norm(targets[matched][j] - p) < 0.03
            rgb[i] = colours[j] if near else GREY
        meshes.append((frames[k], rgb))
    for column, (mesh, rgb) in enumerate(meshes):
        renderer = vtkRenderer()
        renderer.SetViewport(column / columns, 0, (column + 1) / columns, 1)
        renderer.SetBackground(1, 1, 1)
        renderer.AddActor(colour_field_actor(mesh, rgb))
        camera = renderer.GetActiveCamera()
        bounds = mesh.GetBounds()
        centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                  (bounds[4] + bounds[5]) / 2]
        camera.SetFocalPoint(*centre)
        camera.SetPosition(centre[0], centre[1] + 0.3, centre[2] + 3.5)
        camera.SetViewUp(0, 1, 0)
        renderer.ResetCamera()
        window.AddRenderer(renderer)
    save_png(window, out)
    print("wrote", out)


main()
