"""pvpython test: load the ClothTrack plugin, read a sequence, step through time, run a filter.

usage: pvpython test_plugin_reader.py PLUGIN_PATH SCRATCH_DIR [SHARED_DATA_DIR]
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin, scratch = sys.argv[1], sys.argv[2]
shared = sys.argv[3] if len(sys.argv) > 3 else ""
LoadPlugin(plugin, remote=False, ns=globals())


def check(condition, message):
    if not condition:
        print("FAIL: " + message)
        sys.exit(1)


# A small sequence: a tetrahedron rising 1 m per frame.
os.makedirs(scratch, exist_ok=True)
for k in range(6):
    with open(os.path.join(scratch, "tet_%d.obj" % k), "w") as f:
        f.write("v 0 {y} 0\nv 1 {y} 0\nv 0 {y}.5 1\nv 0 {y} 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n".format(y=k))

reader = ClothTrackSequenceReader(FileName=scratch)
reader.FrameRate = 2.0
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
check(times == [0.0, 0.5, 1.0, 1.5, 2.0, 2.5], "time steps %s" % times)

reader.UpdatePipeline(1.5)
frame = servermanager.Fetch(reader)
check(frame.GetNumberOfPoints() == 4, "points %d" % frame.GetNumberOfPoints())
check(abs(frame.GetPoint(0)[1] - 3.0) < 1e-9, "frame at t=1.5 should be frame 3, y=%g" % frame.GetPoint(0)[1])

topology = ClothTrackSurfaceTopology(Input=reader)
topology.UpdatePipeline(0.0)
result = servermanager.Fetch(topology)
check(result.GetFieldData().GetArray("ComponentGenus").GetValue(0) == 0, "genus")

geodesic = ClothTrackGeodesicDistance(Input=reader)
geodesic.SourcePoints = [0]
geodesic.UpdatePipeline(0.0)
distances = servermanager.Fetch(geodesic).GetPointData().GetArray("GeodesicDistance")
check(abs(distances.GetValue(1) - 1.0) < 1e-9, "geodesic distance to vertex 1: %g" % distances.GetValue(1))

selection = ClothTrackTemplateSelection(Input=OutputPort(reader, 1))
selection.Persistence = 1
selection.UpdatePipeline()
template = servermanager.Fetch(selection)
check(template.GetFieldData().GetArray("TemplateFrame").GetValue(0) in range(6), "template frame")

body = ClothTrackBodyModel()
body.ShapeCoefficients = [1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
body.UpdatePipeline()
mesh = servermanager.Fetch(body)
check(5000 <= mesh.GetNumberOfPoints() <= 15000, "body model vertices %d" % mesh.GetNumberOfPoints())
check(mesh.GetPointData().GetArray("SkinWeights").GetNumberOfComponents() == 22, "skin weights")

synthetic = ClothTrackSyntheticCapture(Preset="skirt-turn", NumberOfFrames=3)
synthetic.UpdatePipelineInformation()
check(len(synthetic.TimestepValues) == 3, "synthetic time steps")
synthetic.UpdatePipeline(synthetic.TimestepValues[2])
truth = servermanager.Fetch(synthetic)
check(truth.GetPointData().GetArray("IsGarment") is not None, "synthetic ground truth arrays")

# Template fit: the stage weights reach the filter as repeated (wc, ws, wd, wt) commands.
fit = ClothTrackTemplateFit(Input=OutputPort(reader, 1), Correspondence=OutputPort(reader, 1))
check(len(fit.Stages) == 16, "default stages %s" % list(fit.Stages))
fit.Stages = [1.0, 100.0, 0.0, 0.1, 0.0, 50.0, 10.0, 0.1]
fit.Solver = "L-BFGS"
fit.UpdateVTKObjects()
# Plugin classes are not Python-wrapped in pvpython: read the filter's PrintSelf.
printed = str(fit.GetClientSideObject())
check(printed.count("Stage (wc, ws, wd, wt)") == 2, "stages after setting:\n" + printed)
check("Stage (wc, ws, wd, wt): 0, 50, 10, 0.1" in printed, "second stage:\n" + printed)
check("Solver: L-BFGS" in printed, "solver:\n" + printed)

if shared and os.path.isdir(os.path.join(shared, "vlasic-samba")):
    samba = ClothTrackSequenceReader(FileName=os.path.join(shared, "vlasic-samba"))
    samba.UpdatePipelineInformation()
    check(len(samba.TimestepValues) == 175, "samba frames %d" % len(samba.TimestepValues))
    samba.UpdatePipeline(samba.TimestepValues[100])
    check(servermanager.Fetch(samba).GetNumberOfPoints() == 9971, "samba vertices")
else:
    print("shared data not found: skipping the samba part")

print("plugin reader test passed")
