"""A movie of an aligned sequence: the template in every frame, coloured by its error (or by its
distance to the frame without a ground truth), seen by a fixed camera; or a turntable of one frame.

usage: python3 -m clothtrack.movie OUT [--turntable FRAME] [--size WxH] [--fps FPS]
(OUT is the output folder of `clothtrack align`; renders on the X display, or on a virtual one of its
own when there is none)

Writes OUT/movie/movie_NNNN.png and, when ffmpeg is installed, OUT/movie.mp4.
"""
import argparse
import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

from .virtual_display import VirtualDisplayError, ensure_display


def _read(path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    if reader.GetOutput().GetNumberOfPoints() == 0:
        raise ValueError("%s: unreadable or empty aligned frame" % path)
    return reader.GetOutput()


def write_movie(folder, size=(720, 720), fps=None, turntable=None):
    """Renders the frames; returns the list of PNG paths and the MP4 path (or None)."""
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTextActor

    from clothtrack.rendering import offscreen_window, save_png

    out = Path(folder)
    metrics = json.loads((out / "metrics.json").read_text())
    numbers = metrics["frame_numbers"]
    paths = [out / "aligned" / ("aligned_%04d.vtp" % k) for k in numbers]
    if turntable is not None:
        if turntable not in numbers:
            raise ValueError("frame %d is not among the aligned frames" % turntable)
        frames = [(turntable, 360.0 * step / 72) for step in range(72)]
    else:
        frames = [(k, 0.0) for k in numbers]
    first = _read(paths[0])
    array = "Error" if first.GetPointData().GetArray("Error") else "SurfaceDistance"
    label = "error (m)" if array == "Error" else "distance to frame (m)"
    # One camera for the whole movie: it frames every frame's bounds.
    bounds = [math.inf, -math.inf] * 3
    for path in paths if turntable is None else [paths[numbers.index(turntable)]]:
        b = _read(path).GetBounds()
        for axis in range(3):
            bounds[2 * axis] = min(bounds[2 * axis], b[2 * axis])
            bounds[2 * axis + 1] = max(bounds[2 * axis + 1], b[2 * axis + 1])
    centre = [(bounds[2 * a] + bounds[2 * a + 1]) / 2 for a in range(3)]

    window = offscreen_window(*size)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    window.AddRenderer(renderer)
    mapper = vtkPolyDataMapper()
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    mapper.SetScalarRange(0.0, 0.1)
    lut = mapper.GetLookupTable()
    lut.SetHueRange(0.66, 0.0)
    lut.Build()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(label)
    bar.SetLabelFormat("%.2f")
    bar.SetWidth(0.1)
    bar.SetHeight(0.5)
    bar.SetPosition(0.87, 0.25)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    renderer.AddActor2D(bar)
    text = vtkTextActor()
    text.GetTextProperty().SetColor(0, 0, 0)
    text.GetTextProperty().SetFontSize(18)
    text.SetPosition(12, size[1] - 30)
    renderer.AddActor2D(text)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0], centre[1] + 0.3, centre[2] + 4.0)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera(bounds)

    movie = out / "movie"
    if movie.exists():
        shutil.rmtree(movie)
    movie.mkdir()
    written = []
    current = None
    for index, (k, angle) in enumerate(frames):
        if k != current:
            data = _read(paths[numbers.index(k)])
            mapper.SetInputData(data)
            current = k
        actor.SetOrientation(0, angle, 0)
        actor.SetOrigin(*centre)
        text.SetInput("frame %d%s" % (k, " (template)" if numbers.index(k) == metrics["template_frame"] else ""))
        path = movie / ("movie_%04d.png" % index)
        save_png(window, path)
        written.append(path)
    mp4 = None
    if shutil.which("ffmpeg"):
        rate = fps or (24 if turntable is not None else 25)
        mp4 = out / "movie.mp4"
        subprocess.run(["ffmpeg", "-y", "-loglevel", "error", "-framerate", str(rate), "-i",
                        str(movie / "movie_%04d.png"), "-pix_fmt", "yuv420p", "-vf",
                        "scale=trunc(iw/2)*2:trunc(ih/2)*2", str(mp4)], check=True)
    return written, mp4


def main(argv):
    parser = argparse.ArgumentParser(prog="clothtrack.movie", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("--turntable", type=int, metavar="FRAME", help="turn around this frame instead")
    parser.add_argument("--size", default="720x720")
    parser.add_argument("--fps", type=float)
    args = parser.parse_args(argv[1:])
    try:
        width, height = (int(v) for v in args.size.split("x"))
        with ensure_display():
            written, mp4 = write_movie(args.folder, (width, height), args.fps, args.turntable)
    except (OSError, KeyError, ValueError, subprocess.CalledProcessError, VirtualDisplayError) as error:
        print("clothtrack movie: %s" % error, file=sys.stderr)
        return 1
    print("wrote %d frames in %s" % (len(written), Path(args.folder) / "movie"))
    if mp4:
        print("wrote", mp4)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
