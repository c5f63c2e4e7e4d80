"""The four front ends run the same stages: on a 4-frame synthetic capture the command line
(clothtrack align), a C++ filter chain (example_align_sequence), clothtrack.align in Python and the
ParaView plugin's chain in pvpython must choose the same template frame and give the same aligned
positions (to 1e-9 m; each path uses every core, and results do not depend on the thread count).
"""
import glob
import os
import shutil
import subprocess
import sys
import unittest

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

TOLERANCE = 1e-9  # metres
APP = os.environ.get("CLOTHTRACK_APP")
EXAMPLE = os.environ.get("CLOTHTRACK_EXAMPLE")
PVPYTHON = os.environ.get("CLOTHTRACK_PVPYTHON")
PLUGIN = os.environ.get("CLOTHTRACK_PLUGIN")
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")


def read_positions(pattern):
    frames = []
    for path in sorted(glob.glob(pattern)):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        frames.append(numpy_support.vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(np.float64))
    return np.stack(frames)


class Equivalence(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not APP:
            raise unittest.SkipTest("CLOTHTRACK_APP is not set")
        cls.work = os.path.join(os.environ.get("CLOTHTRACK_TEST_TMP", "/tmp"), "equivalence")
        shutil.rmtree(cls.work, ignore_errors=True)
        os.makedirs(cls.work)
        data = os.path.join(cls.work, "synth")
        subprocess.run([APP, "synth", "--preset", "skirt-turn", "--frames", "4", "--seed", "5", "-o", data],
                       check=True, stdout=subprocess.DEVNULL)
        cls.frames = os.path.join(data, "frames")
        cls.truth = os.path.join(data, "ground_truth")
        out = os.path.join(cls.work, "cli")
        subprocess.run([APP, "align", cls.frames, "-o", out, "--no-report"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        import json
        with open(os.path.join(out, "metrics.json")) as f:
            cls.template_frame = json.load(f)["template_frame"]
        cls.positions = read_positions(os.path.join(out, "aligned", "aligned_*.vtp"))
        assert cls.positions.shape[0] == 4

    def assertSameAlignment(self, template_frame, positions, path):
        self.assertEqual(template_frame, self.template_frame, path + ": another template frame")
        self.assertEqual(positions.shape, self.positions.shape, path)
        # The template frame is the frame itself: the paths have really aligned the others.
        moved = np.abs(self.positions - self.positions[self.template_frame]).max()
        self.assertGreater(moved, 0.01)
        difference = np.abs(positions - self.positions).max()
        self.assertLessEqual(difference, TOLERANCE, "%s differs from the command line by %.3g m" % (path, difference))

    def test_cpp_filter_chain(self):
        if not EXAMPLE:
            self.skipTest("CLOTHTRACK_EXAMPLE is not set")
        out = os.path.join(self.work, "cpp", "aligned.pvd")
        run = subprocess.run([EXAMPLE, self.frames, self.truth, out], check=True, capture_output=True, text=True)
        template_frame = int(run.stdout.split("template frame ")[1].split()[0])
        positions = read_positions(os.path.join(self.work, "cpp", "aligned", "*.vtp"))
        self.assertSameAlignment(template_frame, positions, "C++ filter chain")

    def test_python_align(self):
        import clothtrack
        result = clothtrack.align(self.frames)
        self.assertSameAlignment(result.template_frame, result.positions.astype(np.float64), "clothtrack.align")

    def test_plugin_chain(self):
        if not (PVPYTHON and PLUGIN):
            self.skipTest("the ParaView plugin is not built (CLOTHTRACK_PVPYTHON, CLOTHTRACK_PLUGIN)")
        out = os.path.join(self.work, "plugin.npz")
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        display = os.path.join(ROOT, "python_wrapping", "clothtrack", "virtual_display.py")
        subprocess.run([sys.executable, display, "--", PVPYTHON, "--force-offscreen-rendering",
                        os.path.join(ROOT, "tests", "paraview", "equivalence_plugin_chain.py"), PLUGIN,
                        self.frames, out], check=True, env=env, stdout=subprocess.DEVNULL)
        result = np.load(out)
        self.assertSameAlignment(int(result["template_frame"]), result["positions"], "plugin chain")


if __name__ == "__main__":
    unittest.main()
