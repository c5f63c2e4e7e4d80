"""pvpython test: the whole pipeline built from the plugin's proxies (the example script's own
functions) on a short synthetic capture: numbers, Play without recomputation, and a screenshot
compared with a committed baseline image.

usage: pvpython test_plugin_pipeline.py PLUGIN_PATH CLOTHTRACK_APP SCRATCH_DIR BASELINE_DIR
Set CLOTHTRACK_UPDATE_BASELINES=1 to (re)write the baseline instead of comparing with it.
"""
import os
import shutil
import subprocess
import sys

import paraview.simple as simple
from paraview.simple import Hide, LoadPlugin, SaveScreenshot

plugin, app, scratch, baselines = sys.argv[1:5]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "paraview_plugin", "examples"))
import clothtrack_pipeline  # noqa: E402

LoadPlugin(plugin, remote=False)
SIZE = (400, 400)
# Mean per-pixel difference above which a render counts as different (vtkImageDifference's
# thresholded error; identical renders give 0).
IMAGE_TOLERANCE = 2.0


def check(condition, message):
    if not condition:
        print("FAIL: " + message)
        sys.exit(1)


def image_difference(a, b):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference

    readers = []
    for path in (a, b):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.Update()
    return difference.GetThresholdedError()


shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
data = os.path.join(scratch, "synth")
subprocess.run([app, "synth", "--preset", "skirt-turn", "--frames", "4", "--seed", "3", "--voxel", "0.02",
                "-o", data],
               check=True, stdout=subprocess.DEVNULL)

pipeline = clothtrack_pipeline.build_pipeline(os.path.join(data, "frames"), os.path.join(data, "ground_truth"),
                                              shape_frames=2)
# Creating Play Sequence runs the pipeline (its time steps are the fitted frames); playing must
# not run it again.
aligned = pipeline["fit"].GetClientSideObject().GetOutputDataObject(0)
check(aligned.GetNumberOfBlocks() == 4, "aligned frames %d" % aligned.GetNumberOfBlocks())
fitted_at = aligned.GetMTime()
view = clothtrack_pipeline.show_aligned(pipeline, SIZE)

frames = pipeline["frames"]
frames.UpdatePipelineInformation()
times = list(pipeline["play"].TimestepValues)
check(times == list(frames.TimestepValues), "Play times %s, frames %s" % (times, list(frames.TimestepValues)))
paths = clothtrack_pipeline.save_frames(pipeline, view, scratch, SIZE)
check(len(paths) == 3 and all(os.path.getsize(p) > 1000 for p in paths), "screenshots %s" % paths)
check(pipeline["fit"].GetClientSideObject().GetOutputDataObject(0).GetMTime() == fitted_at,
      "the template fit ran again while playing")

errors = pipeline["error"].GetClientSideObject().GetOutputDataObject(1)
check(errors.GetNumberOfRows() == 4, "error rows %d" % errors.GetNumberOfRows())
for k in range(4):
    mean = errors.GetValueByName(k, "Mean").ToDouble()
    within = errors.GetValueByName(k, "Within10cm").ToDouble()
    print("frame %d: mean error %.4f m, within 10 cm %.3f" % (k, mean, within))
    check(mean < 0.04 and within > 0.95, "frame %d: mean %g, within 10 cm %g" % (k, mean, within))

# Template Selection with the body fit chooses by pose, as Patch Correspondence did; without it,
# by area ratio. Its criteria table lists each frame's distance from the rest pose.
def template_frame(proxy):
    """The TemplateFrame field value of a proxy's first output (the first block of a collection)."""
    data = proxy.GetClientSideObject().GetOutputDataObject(0)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    return int(data.GetFieldData().GetArray("TemplateFrame").GetTuple1(0))


chosen = template_frame(pipeline["correspondence"])
selection = simple.ClothTrackTemplateSelection(Input=simple.OutputPort(pipeline["frames"], 1),
                                               BodyFit=simple.OutputPort(pipeline["body"], 0))
selection.UpdatePipeline()
table = selection.GetClientSideObject().GetOutputDataObject(1)
distances = [table.GetValueByName(k, "RestPoseDistance").ToDouble() for k in range(table.GetNumberOfRows())]
by_pose = template_frame(selection)
print("template by pose: frame %d (rest-pose distances %s)" % (by_pose, ["%.2f" % d for d in distances]))
check(by_pose == chosen, "Template Selection chose %d, Patch Correspondence %d" % (by_pose, chosen))
candidates = [d for k, d in enumerate(distances) if table.GetValueByName(k, "Candidate").ToInt()]
check(distances[chosen] == min(candidates), "the chosen frame is not the candidate nearest the rest pose")
selection.TemplateCriterion = "Area ratio"
selection.UpdatePipeline()
table = selection.GetClientSideObject().GetOutputDataObject(1)
ratios = [table.GetValueByName(k, "AreaRatio").ToDouble() for k in range(table.GetNumberOfRows())]
by_area = template_frame(selection)
check(ratios[by_area] == min(r for k, r in enumerate(ratios) if table.GetValueByName(k, "Candidate").ToInt()),
      "with the area ratio, frame %d is not the most uniform candidate" % by_area)
simple.Delete(selection)

# Model Choice takes several template fits' summaries (here one fit's twice): one row each, the
# means of their Stretch and MeanSurfaceDistance columns, and the first kept when they tie.
summary = pipeline["fit"].GetClientSideObject().GetOutputDataObject(1)
choice = simple.ClothTrackModelChoice(Input=[simple.OutputPort(pipeline["fit"], 1)] * 2)
choice.UpdatePipeline()
rows = choice.GetClientSideObject().GetOutputDataObject(0)
check(rows.GetNumberOfRows() == 2, "model choice rows %d" % rows.GetNumberOfRows())
stretch = [summary.GetValueByName(k, "Stretch").ToDouble() for k in range(summary.GetNumberOfRows())]
mean_stretch = rows.GetValueByName(1, "MeanStretch").ToDouble()
check(abs(mean_stretch - sum(stretch) / len(stretch)) < 1e-12, "model choice mean stretch %g" % mean_stretch)
check([rows.GetValueByName(k, "Kept").ToInt() for k in range(2)] == [1, 0], "model choice did not keep the first of two ties")
simple.Delete(choice)

shot = paths[-1]
baseline = os.path.join(baselines, "plugin_pipeline_aligned.png")
if os.environ.get("CLOTHTRACK_UPDATE_BASELINES") == "1":
    shutil.copyfile(shot, baseline)
    print("wrote baseline", baseline)
check(os.path.exists(baseline), "no baseline %s (run with CLOTHTRACK_UPDATE_BASELINES=1)" % baseline)
difference = image_difference(shot, baseline)
print("image difference to the baseline: %.3f (tolerance %.1f)" % (difference, IMAGE_TOLERANCE))
check(difference <= IMAGE_TOLERANCE, "the render differs from %s by %.3f; see %s" % (baseline, difference, shot))

# The comparison does see a broken render: the same view without the template.
Hide(pipeline["play"], view)
empty = os.path.join(scratch, "empty.png")
SaveScreenshot(empty, view, ImageResolution=list(SIZE))
broken = image_difference(empty, baseline)
print("image difference of an empty view: %.3f" % broken)
check(broken > IMAGE_TOLERANCE, "an empty view passes as the baseline (%.3f)" % broken)
print("plugin pipeline test passed")
