"""The four front ends run the same stages: on a 4-frame synthetic capture the command line
(clothtrack align), a C++ filter chain (example_align_sequence), clothtrack.align in Python and the
ParaView plugin's chain in pvpython must choose the same template frame and give the same aligned
positions (to 1e-9 m; each path uses every core, and results do not depend on the thread count).
Under two body models, the command line, clothtrack.align and the plugin's chains (Model Choice)
must also keep the same one, by the same figures; under two template frames, the command line and
clothtrack.align must too.
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
        # Captured at 2.5 cm voxels: the front ends' agreement does not depend on the resolution.
        subprocess.run([APP, "synth", "--preset", "skirt-turn", "--frames", "4", "--seed", "5", "--voxel", "0.025",
                        "-o", data],
                       check=True, stdout=subprocess.DEVNULL)
        cls.frames = os.path.join(data, "frames")
        cls.truth = os.path.join(data, "ground_truth")
        # A second body model, its head, neck and shoulders spread wider.
        cls.model = os.path.join(cls.work, "wide.vtp")
        subprocess.run([APP, "body-model", "-o", cls.model, "--spread", "headSize=3", "--spread", "neckLength=3",
                        "--spread", "shoulderWidth=2"], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        out = os.path.join(cls.work, "cli")
        subprocess.run([APP, "align", cls.frames, "-o", out, "--no-report", "--model", "builtin", "--model",
                        cls.model], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        import json
        with open(os.path.join(out, "metrics.json")) as f:
            cls.metrics = json.load(f)
        # The kept model's alignment is in OUT, the other's in OUT/models/<i>_<name>.
        cls.kept = cls.metrics["model_choice"]["kept"]
        folders = [out if i == cls.kept else os.path.join(out, m["folder"])
                   for i, m in enumerate(cls.metrics["model_choice"]["models"])]
        cls.model_positions = [read_positions(os.path.join(f, "aligned", "aligned_*.vtp")) for f in folders]
        with open(os.path.join(folders[0], "metrics.json")) as f:
            builtin_metrics = json.load(f)
        cls.template_frame = builtin_metrics["template_frame"]
        cls.frames_by_pose = builtin_metrics["template_frames_by_pose"]
        cls.positions = cls.model_positions[0]  # the built-in model's, as the other paths use it
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
        stages = set()
        result = clothtrack.align(self.frames, model=["builtin", self.model],
                                  progress=lambda stage, _fraction: stages.add(stage))
        # Under several models each stage's progress names its model.
        self.assertIn("builtin: body fit", stages)
        self.assertIn(self.model + ": template fit", stages)
        choice = result.metrics["model_choice"]
        self.assertEqual(choice["kept"], self.kept)
        self.assertIs(result, result.model_alignments[self.kept])
        self.assertEqual(result.metrics["model"], self.metrics["model"])
        for mine, cli in zip(choice["models"], self.metrics["model_choice"]["models"]):
            self.assertEqual(mine["model"], cli["model"])
            self.assertGreater(mine["seconds_total"], 0.5)
            for key in ("mean_stretch", "mean_surface_distance_m"):
                self.assertAlmostEqual(mine[key], cli[key], delta=1e-12, msg=key)
        builtin = result.model_alignments[0]
        self.assertEqual(builtin.model, "builtin")
        # A sequence is aligned under one template frame; the frames by pose are reported.
        self.assertNotIn("template_choice", builtin.metrics)
        self.assertEqual(builtin.metrics["template_frames_by_pose"], self.frames_by_pose)
        self.assertSameAlignment(builtin.template_frame, builtin.positions.astype(np.float64), "clothtrack.align")
        other = result.model_alignments[1].positions.astype(np.float64)
        difference = np.abs(other - self.model_positions[1]).max()
        self.assertLessEqual(difference, TOLERANCE, "clothtrack.align under %s differs by %.3g m" % (self.model, difference))
        # The two models give two alignments: the comparison above is not of one alignment twice.
        self.assertGreater(np.abs(other - builtin.positions).max(), 1e-4)

    def test_python_template_choice(self):
        import json
        import clothtrack
        out = os.path.join(self.work, "cli_templates")
        subprocess.run([APP, "align", self.frames, "-o", out, "--no-report", "--template-candidates", "2"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "metrics.json")) as f:
            cli = json.load(f)
        stages = set()
        result = clothtrack.align(self.frames, template_candidates=2,
                                  progress=lambda stage, _fraction: stages.add(stage))
        choice = result.metrics["template_choice"]
        self.assertEqual(choice["criterion"], cli["template_choice"]["criterion"])
        self.assertEqual(choice["kept"], cli["template_choice"]["kept"])
        self.assertEqual(result.template_frame, cli["template_frame"])
        self.assertEqual(result.metrics["template_frames_by_pose"], cli["template_frames_by_pose"])
        self.assertEqual(len(choice["candidates"]), 2)
        for mine, theirs in zip(choice["candidates"], cli["template_choice"]["candidates"]):
            self.assertEqual(mine["template_frame"], theirs["template_frame"])
            for key in ("mean_stretch", "mean_surface_distance_m"):
                self.assertAlmostEqual(mine[key], theirs[key], delta=1e-12, msg=key)
        # The second candidate reuses the first's body fit: its stages are named, the body fit not.
        second = choice["candidates"][1]["template_frame"]
        self.assertIn("template frame %d: template fit" % second, stages)
        self.assertNotIn("template frame %d: body fit" % second, stages)
        self.assertIs(result, result.template_alignments[choice["kept"]])
        positions = read_positions(os.path.join(out, "aligned", "aligned_*.vtp"))
        difference = np.abs(result.positions.astype(np.float64) - positions).max()
        self.assertLessEqual(difference, TOLERANCE, "clothtrack.align differs by %.3g m" % difference)
        # The two candidates are two alignments, each under its own template.
        a, b = result.template_alignments
        self.assertNotEqual(a.template_frame, b.template_frame)
        self.assertNotEqual(a.positions.shape, b.positions.shape)

    def test_plugin_chain(self):
        if not (PVPYTHON and PLUGIN):
            self.skipTest("the ParaView plugin is not built (CLOTHTRACK_PVPYTHON, CLOTHTRACK_PLUGIN)")
        out = os.path.join(self.work, "plugin.npz")
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        display = os.path.join(ROOT, "python_wrapping", "clothtrack", "virtual_display.py")
        subprocess.run([sys.executable, display, "--", PVPYTHON, "--force-offscreen-rendering",
                        os.path.join(ROOT, "tests", "paraview", "equivalence_plugin_chain.py"), PLUGIN,
                        self.frames, self.model, out], check=True, env=env, stdout=subprocess.DEVNULL)
        result = np.load(out)
        self.assertSameAlignment(int(result["template_frame_0"]), result["positions_0"], "plugin chain")
        difference = np.abs(result["positions_1"] - self.model_positions[1]).max()
        self.assertLessEqual(difference, TOLERANCE, "plugin chain under %s differs by %.3g m" % (self.model, difference))
        self.assertEqual(int(result["kept"]), self.kept, "Model Choice kept another alignment")
        for index, cli in enumerate(self.metrics["model_choice"]["models"]):
            self.assertAlmostEqual(result["MeanStretch"][index], cli["mean_stretch"], delta=1e-12)
            self.assertAlmostEqual(result["MeanSurfaceDistance"][index], cli["mean_surface_distance_m"], delta=1e-12)


if __name__ == "__main__":
    unittest.main()
