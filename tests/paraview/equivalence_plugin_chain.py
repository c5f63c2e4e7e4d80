"""pvpython helper of tests/python/test_equivalence.py: the plugin's filter chain (the example
pipeline's proxies) on FRAMES; writes the template frame and the aligned positions to OUT.npz.

usage: pvpython equivalence_plugin_chain.py PLUGIN FRAMES OUT.npz
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin
from vtkmodules.util import numpy_support

plugin, frames, out = sys.argv[1:4]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "paraview_plugin", "examples"))
import clothtrack_pipeline  # noqa: E402

LoadPlugin(plugin, remote=False)
pipeline = clothtrack_pipeline.build_pipeline(frames, shape_frames=4)
fit = pipeline["fit"]
fit.UpdatePipeline()
aligned = servermanager.Fetch(fit, 0)
blocks = [aligned.GetBlock(k) for k in range(aligned.GetNumberOfBlocks())]
positions = np.stack([numpy_support.vtk_to_numpy(b.GetPoints().GetData()).astype(np.float64) for b in blocks])
template_frame = int(blocks[0].GetFieldData().GetArray("TemplateFrame").GetTuple1(0))
np.savez(out, positions=positions, template_frame=template_frame)
print("plugin chain: %d frames, template frame %d" % (len(blocks), template_frame))
