"""The whole ClothTrack pipeline in ParaView, from pvpython or pvbatch.

    pvpython --force-offscreen-rendering clothtrack_pipeline.py PLUGIN FRAMES OUT [--ground-truth GT]
        [--frame-rate FPS] [--state]

PLUGIN is the built ClothTrack.so, FRAMES a folder of frames (e.g. ../shared/data/vlasic-samba, or the
frames/ folder that `clothtrack synth` writes) and GT a ground-truth sequence with one connectivity
(the ground_truth/ folder of `clothtrack synth`). OUT receives screenshots of the aligned template
(coloured by error with a ground truth, by distance to the frame's surface without) at the first,
middle and last frames and, with --state, a ParaView state file to open in the GUI. Without a display,
run it under a virtual one: `python3 python_wrapping/clothtrack/virtual_display.py -- pvpython ...`.

The pipeline, as in the GUI's ClothTrack menu:
    Sequence Reader -> Body Fit -> Patch Correspondence -> Template Fit -> (Alignment Error) -> Play Sequence
"""
import argparse
import os

from paraview.simple import (  # noqa: F401
    ColorBy, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction, LoadPlugin, OutputPort,
    Render, ResetCamera, SaveScreenshot, SaveState, Show)


def build_pipeline(frames, ground_truth=None, frame_rate=25.0, shape_frames=8):
    """Creates the pipeline proxies; returns them by name. Nothing runs until a proxy is updated."""
    from paraview import simple

    p = {}
    p["frames"] = simple.ClothTrackSequenceReader(FileName=frames)
    p["frames"].FrameRate = frame_rate
    p["body"] = simple.ClothTrackBodyFit(Input=OutputPort(p["frames"], 1))
    p["body"].ShapeFrames = shape_frames
    p["correspondence"] = simple.ClothTrackPatchCorrespondence(
        Input=OutputPort(p["frames"], 1), Landmarks=OutputPort(p["body"], 1))
    p["fit"] = simple.ClothTrackTemplateFit(
        Input=OutputPort(p["frames"], 1), Correspondence=OutputPort(p["correspondence"], 0),
        Landmarks=OutputPort(p["body"], 1), Bodies=OutputPort(p["body"], 0))
    aligned = OutputPort(p["fit"], 0)
    if ground_truth:
        p["truth"] = simple.ClothTrackSequenceReader(FileName=ground_truth)
        p["truth"].FrameRate = frame_rate
        p["error"] = simple.ClothTrackAlignmentError(Input=aligned, GroundTruth=OutputPort(p["truth"], 1))
        aligned = OutputPort(p["error"], 0)
    p["play"] = simple.ClothTrackPlaySequence(Input=aligned)
    return p


def show_aligned(pipeline, size=(640, 640), error_range=(0.0, 0.1)):
    """Shows the played sequence coloured by Error (or SurfaceDistance); returns the view."""
    play = pipeline["play"]
    play.UpdatePipelineInformation()
    GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    display = Show(play, view)
    array = "Error" if "error" in pipeline else "SurfaceDistance"
    ColorBy(display, ("POINTS", array))
    GetColorTransferFunction(array).RescaleTransferFunction(*error_range)
    display.SetScalarBarVisibility(view, True)
    view.ViewTime = play.TimestepValues[0]
    view.CameraPosition = [0.0, 1.0, 4.0]
    view.CameraFocalPoint = [0.0, 1.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    ResetCamera(view)
    return view


def save_frames(pipeline, view, out, size=(640, 640)):
    """Screenshots at the first, middle and last frames; returns their paths."""
    times = list(pipeline["play"].TimestepValues)
    paths = []
    for index in sorted({0, len(times) // 2, len(times) - 1}):
        view.ViewTime = times[index]
        Render(view)
        path = os.path.join(out, "aligned_%04d.png" % index)
        SaveScreenshot(path, view, ImageResolution=list(size))
        paths.append(path)
    return paths


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("plugin")
    parser.add_argument("frames")
    parser.add_argument("out")
    parser.add_argument("--ground-truth")
    parser.add_argument("--frame-rate", type=float, default=25.0)
    parser.add_argument("--state", action="store_true", help="also write OUT/clothtrack.pvsm")
    args = parser.parse_args()
    LoadPlugin(args.plugin, remote=False)  # adds the ClothTrack proxies to paraview.simple
    os.makedirs(args.out, exist_ok=True)
    pipeline = build_pipeline(args.frames, args.ground_truth, args.frame_rate)
    view = show_aligned(pipeline)
    for path in save_frames(pipeline, view, args.out):
        print("wrote", path)
    if args.state:
        SaveState(os.path.join(args.out, "clothtrack.pvsm"))
        print("wrote", os.path.join(args.out, "clothtrack.pvsm"))


if __name__ == "__main__":
    main()
