"""pvpython helper of tests/python/test_equivalence.py: the plugin's filter chains (the example
pipeline's proxies) on FRAMES under the built-in model and MODEL, one kept by Model Choice; writes
each chain's template frame and aligned positions, the kept index and the choice's figures to OUT.npz.

usage: pvpython equivalence_plugin_chain.py PLUGIN FRAMES MODEL OUT.npz
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin
from vtkmodules.util import numpy_support

plugin, frames, model, out = sys.argv[1:5]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "paraview_plugin", "examples"))
import clothtrack_pipeline  # noqa: E402

LoadPlugin(plugin, remote=False)
pipeline = clothtrack_pipeline.build_pipeline(frames, shape_frames=4, models=["builtin", model])
arrays = {"kept": pipeline["kept"]}
for index, chain in enumerate(pipeline["chains"]):
    aligned = servermanager.Fetch(chain["fit"], 0)
    blocks = [aligned.GetBlock(k) for k in range(aligned.GetNumberOfBlocks())]
    arrays["positions_%d" % index] = np.stack(
        [numpy_support.vtk_to_numpy(b.GetPoints().GetData()).astype(np.float64) for b in blocks])
    arrays["template_frame_%d" % index] = int(blocks[0].GetFieldData().GetArray("TemplateFrame").GetTuple1(0))
rows = servermanager.Fetch(pipeline["choice"])
for column in ("MeanStretch", "MeanSurfaceDistance"):
    arrays[column] = [rows.GetValueByName(k, column).ToDouble() for k in range(rows.GetNumberOfRows())]
np.savez(out, **arrays)
print("plugin chains: %d, kept %d" % (len(pipeline["chains"]), pipeline["kept"]))
