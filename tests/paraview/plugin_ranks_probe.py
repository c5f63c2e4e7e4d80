"""pvbatch script run by test_plugin_ranks.py, alone and under mpirun --mpi: builds the example
pipeline on a synthetic capture, writes the aligned sequence with the plugin's writer and prints,
as one JSON line, what every stage produced (point, cell and row totals over all processes), the
per-frame errors and a checksum of the aligned positions.

usage: pvbatch [--mpi] plugin_ranks_probe.py PLUGIN_PATH CAPTURE_DIR OUT_PVD
"""
import json
import os
import sys

import paraview.simple as simple
from paraview import servermanager

plugin, capture, out_pvd = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "paraview_plugin", "examples"))
import clothtrack_pipeline  # noqa: E402

simple.LoadPlugin(plugin, remote=False)
pipeline = clothtrack_pipeline.build_pipeline(os.path.join(capture, "frames"), os.path.join(capture, "ground_truth"),
                                              shape_frames=2)
totals = {}
for name in ("frames", "body", "correspondence", "fit", "truth", "error", "play"):
    proxy = pipeline[name]
    proxy.UpdatePipeline()
    for port in range(proxy.SMProxy.GetNumberOfOutputPorts()):
        info = proxy.GetDataInformation(port)
        totals["%s:%d" % (name, port)] = [info.GetNumberOfPoints(), info.GetNumberOfCells(), info.GetNumberOfRows()]

errors = pipeline["error"].GetClientSideObject().GetOutputDataObject(1)
per_frame = [errors.GetValueByName(k, "Mean").ToDouble() for k in range(errors.GetNumberOfRows())]
aligned = pipeline["fit"].GetClientSideObject().GetOutputDataObject(0)
checksum = []
for b in range(aligned.GetNumberOfBlocks()):
    points = aligned.GetBlock(b).GetPoints()
    checksum.append(sum(sum(points.GetPoint(i)) for i in range(points.GetNumberOfPoints())))

writer = servermanager._getPyProxy(servermanager.CreateProxy("writers", "ctMeshSequenceWriter"))
writer.Input = simple.OutputPort(pipeline["fit"], 0)
writer.FileName = out_pvd
writer.UpdatePipeline()
print("PROBE " + json.dumps({"ranks": servermanager.ActiveConnection.GetNumberOfDataPartitions(),
                             "totals": totals, "errors": per_frame, "checksum": checksum}))
