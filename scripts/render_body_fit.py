#!/usr/bin/env python3
"""Render fitted bodies inside their frames (the frame translucent, the body in brown, the
transferred landmarks as blue dots), one column per frame, front and side views.

usage: PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 scripts/render_body_fit.py \
           [--unit U] [--up AXIS] OUT.png BODY_FIT_FOLDER FRAME_FILE:INDEX [FRAME_FILE:INDEX ...]
BODY_FIT_FOLDER is the output of 'clothtrack body-fit' (bodies/ and landmarks/ inside it, in metres
with Y up); give the frames' --unit and --up as given to body-fit, so that they are read the same way.
"""
import argparse
import glob
import os

import clothtrack
from clothtrack.rendering import colour_actor, offscreen_window, save_png
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkGlyph3D, vtkThreshold
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkRenderingCore import vtkRenderer
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def landmark_actor(landmarks):
    valid = vtkThreshold()
    valid.SetInputData(landmarks)
    valid.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "Valid")
    valid.SetLowerThreshold(0.5)
    valid.SetUpperThreshold(1.5)
    valid.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    geometry = vtkGeometryFilter()
    geometry.SetInputConnection(valid.GetOutputPort())
    sphere = vtkSphereSource()
    sphere.SetRadius(0.012)
    glyphs = vtkGlyph3D()
    glyphs.SetInputConnection(geometry.GetOutputPort())
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.ScalingOff()
    return colour_actor(glyphs.GetOutputPort(), (0.1, 0.3, 0.95))


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("--unit", default="m", help="the frames' length unit (as body-fit's --unit)")
    parser.add_argument("--up", default="y", help="the frames' up axis (as body-fit's --up)")
    parser.add_argument("out")
    parser.add_argument("folder")
    parser.add_argument("specs", nargs="+", metavar="FRAME_FILE:INDEX")
    args = parser.parse_args()
    out, folder, specs = args.out, args.folder, args.specs
    columns = len(specs)
    window = offscreen_window(360 * columns, 1200)
    for column, spec in enumerate(specs):
        path, index = spec.rsplit(":", 1)
        index = int(index)
        frame = clothtrack.read_sequence(path, length_unit=args.unit, up_axis=args.up)[0]
        bodies = sorted(glob.glob(os.path.join(folder, "bodies", "*.vtp")))
        marks = sorted(glob.glob(os.path.join(folder, "landmarks", "*.vtp")))
        body = read_vtp(bodies[index])
        landmarks = read_vtp(marks[index])
        for row, side in enumerate((False, True)):
            renderer = vtkRenderer()
            renderer.SetViewport(column / columns, 0.5 * (1 - row), (column + 1) / columns,
                                 0.5 * (2 - row))
            renderer.SetBackground(1, 1, 1)
            renderer.AddActor(colour_actor(body, (0.6, 0.38, 0.22), smooth_normals=True))
            renderer.AddActor(colour_actor(frame, (0.75, 0.8, 0.9), 0.35, smooth_normals=True))
            renderer.AddActor(landmark_actor(landmarks))
            bounds = frame.GetBounds()
            centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                      (bounds[4] + bounds[5]) / 2]
            camera = renderer.GetActiveCamera()
            camera.SetFocalPoint(*centre)
            offset = (3.5, 0.3, 0.0) if side else (0.0, 0.3, 3.5)
            camera.SetPosition(centre[0] + offset[0], centre[1] + offset[1], centre[2] + offset[2])
            camera.SetViewUp(0, 1, 0)
            renderer.ResetCamera()
            camera.Zoom(1.05)
            window.AddRenderer(renderer)
    save_png(window, out)
    print("wrote", out)


main()
