"""The whole ClothTrack pipeline in ParaView, from pvpython or pvbatch.

    pvpython --force-offscreen-rendering clothtrack_pipeline.py PLUGIN FRAMES OUT [--ground-truth GT]
        [--frame-rate FPS] [--model builtin|MODEL.vtp ...] [--state]

PLUGIN is the built ClothTrack.so, FRAMES a folder of frames (e.g. ../shared/data/vlasic-samba, or the
frames/ folder that `clothtrack synth` writes) and GT a ground-truth sequence with one connectivity
(the ground_truth/ folder of `clothtrack synth`). OUT receives screenshots of the aligned template
(coloured by error with a ground truth, by distance to the frame's surface without) at the first,
middle and last frames and, with --state, a ParaView state file to open in the GUI. Without a display,
run it under a virtual one: `python3 python_wrapping/clothtrack/virtual_display.py -- pvpython ...`.

The pipeline, as in the GUI's ClothTrack menu:
    Sequence Reader -> Body Fit -> Patch Correspondence -> Template Fit -> (Alignment Error) -> Play Sequence

With --model given twice or more (`builtin` or a body model file, as for `clothtrack align --model`),
one Body Fit -> Patch Correspondence -> Template Fit chain is built per model, each Body Fit reading
its model with a Body Model Reader, and Model Choice over the Template Fits' Summary outputs keeps one
alignment, as `clothtrack align --model A --model B` does; the kept chain is the one shown.
"""
import argparse
import os

from paraview.simple import (  # noqa: F401
    ColorBy, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction, LoadPlugin, OutputPort,
    Render, ResetCamera, SaveScreenshot, SaveState, Show)


BUILTIN_MODEL = "builtin"


def _alignment_chain(frames, model, shape_frames):
    """Body Fit -> Patch Correspondence -> Template Fit on the reader `frames` under `model`
    ("builtin" or a body model file); returns the proxies by name."""
    from paraview import simple

    chain = {"model": model}
    sequence = OutputPort(frames, 1)
    chain["body"] = simple.ClothTrackBodyFit(Input=sequence)
    chain["body"].ShapeFrames = shape_frames
    if model != BUILTIN_MODEL:
        if not os.path.isfile(model):
            raise FileNotFoundError("%s: no such body model file" % model)
        chain["body model"] = simple.ClothTrackBodyModelReader(FileName=model)
        chain["body"].BodyModel = chain["body model"]
    chain["correspondence"] = simple.ClothTrackPatchCorrespondence(
        Input=sequence, Landmarks=OutputPort(chain["body"], 1))
    chain["fit"] = simple.ClothTrackTemplateFit(
        Input=sequence, Correspondence=OutputPort(chain["correspondence"], 0),
        Landmarks=OutputPort(chain["body"], 1), Bodies=OutputPort(chain["body"], 0))
    return chain


def kept_alignment(choice):
    """Runs the alignments behind a Model Choice proxy; returns the index of the one it keeps."""
    from paraview import servermanager

    choice.UpdatePipeline()
    table = servermanager.Fetch(choice)
    return int(table.GetFieldData().GetArray("KeptAlignment").GetTuple1(0))


def build_pipeline(frames, ground_truth=None, frame_rate=25.0, shape_frames=8, models=None):
    """Creates the pipeline proxies; returns them by name ("body", "correspondence" and "fit" are the
    kept chain's). Under one model nothing runs until a proxy is updated. Under several (`models`, a
    list of "builtin" and model files), building runs the alignments, since the one Model Choice
    keeps is the one played; every chain is in "chains", the choice in "choice" and the kept
    chain's index in "kept"."""
    from paraview import simple

    models = list(models) if models else [BUILTIN_MODEL]
    p = {}
    p["frames"] = simple.ClothTrackSequenceReader(FileName=frames)
    p["frames"].FrameRate = frame_rate
    p["chains"] = [_alignment_chain(p["frames"], model, shape_frames) for model in models]
    kept = 0
    if len(models) > 1:
        p["choice"] = simple.ClothTrackModelChoice(Input=[OutputPort(c["fit"], 1) for c in p["chains"]])
        kept = kept_alignment(p["choice"])
    p["kept"] = kept
    p.update({k: p["chains"][kept][k] for k in ("body", "correspondence", "fit")})
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
    parser.add_argument("--model", action="append", metavar="MODEL",
                        help="body model: builtin or a model file; twice or more to keep one by Model Choice")
    parser.add_argument("--state", action="store_true", help="also write OUT/clothtrack.pvsm")
    args = parser.parse_args()
    LoadPlugin(args.plugin, remote=False)  # adds the ClothTrack proxies to paraview.simple
    os.makedirs(args.out, exist_ok=True)
    pipeline = build_pipeline(args.frames, args.ground_truth, args.frame_rate, models=args.model)
    if "choice" in pipeline:
        print("kept the alignment under", pipeline["chains"][pipeline["kept"]]["model"])
    view = show_aligned(pipeline)
    for path in save_frames(pipeline, view, args.out):
        print("wrote", path)
    if args.state:
        SaveState(os.path.join(args.out, "clothtrack.pvsm"))
        print("wrote", os.path.join(args.out, "clothtrack.pvsm"))


if __name__ == "__main__":
    main()
