"""clothtrack.align: the whole pipeline in one Python call, on a short synthetic skirt capture
written by `clothtrack synth` (with its ground truth), and its errors for bad input."""

import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import clothtrack

FRAMES = 4


@unittest.skipUnless(os.environ.get("CLOTHTRACK_APP"), "CLOTHTRACK_APP (the clothtrack app) is not set")
class AlignTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        cls.data = os.path.join(cls.folder.name, "synth")
        subprocess.run([os.environ["CLOTHTRACK_APP"], "synth", "--preset", "skirt-turn", "--frames", str(FRAMES),
                        "--seed", "3", "--voxel", "0.02", "-o", cls.data], check=True, capture_output=True)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_aligns_with_the_ground_truth(self):
        stages = set()
        result = clothtrack.align(os.path.join(self.data, "frames"),
                                  ground_truth=os.path.join(self.data, "ground_truth"), shape_frames=2,
                                  progress=lambda stage, fraction: stages.add(stage))
        self.assertEqual(stages, {"body fit", "template selection", "correspondence", "template fit",
                                  "alignment error"})
        n = result.aligned[0].GetNumberOfPoints()
        self.assertEqual(result.positions.shape, (FRAMES, n, 3))
        self.assertEqual(result.faces.shape[1], 3)
        self.assertIn(result.template_frame, range(FRAMES))
        self.assertEqual(result.errors.shape, (FRAMES, n))
        m = result.metrics
        self.assertEqual(m["frames"], FRAMES)
        # A short, slow turn: about a centimetre (measured 0.98 cm).
        self.assertLess(m["mean_vertex_error_m"], 0.03)
        self.assertGreater(m["within_10cm"], 0.97)
        self.assertLess(m["mean_surface_distance_m"], 0.01)
        self.assertEqual(len(m["per_frame_mean_error_m"]), FRAMES)
        # Each frame judged without the truth: an accurate result is not doubtful.
        self.assertEqual(len(m["per_frame_confidence"]), FRAMES)
        self.assertEqual(m["doubtful_frames"], [])
        self.assertEqual(m["per_frame_fit_attempts"], [1] * FRAMES)
        # ... and against the template its fitted body poses: the template frame is that template.
        body = m["per_frame_body_distance_m"]
        self.assertEqual(len(body), FRAMES)
        self.assertLess(body[result.template_frame], 1e-6)
        self.assertLess(max(d for d in body if d is not None), 0.055)
        others = np.delete(result.errors, result.template_frame, axis=0)
        self.assertAlmostEqual(m["mean_vertex_error_m"], np.nanmean(others), places=9)
        # At the template frame only the capture's own deviation from the truth remains (measured 0.6 cm
        # with 1.5 cm voxels).
        self.assertLess(m["per_frame_mean_error_m"][result.template_frame], 0.01)
        # The template really moves: frames differ from the template frame.
        moved = np.linalg.norm(result.positions - result.positions[result.template_frame], axis=2).mean(1)
        self.assertGreater(moved.max(), 0.01)

    def test_a_chosen_template_frame_and_frames_as_polydata(self):
        frames = clothtrack.read_sequence(os.path.join(self.data, "frames"))
        result = clothtrack.align(frames[:3], template_frame=1, shape_frames=2, solver="lbfgs")
        self.assertEqual(result.template_frame, 1)
        self.assertEqual(result.positions.shape[0], 3)
        self.assertIsNone(result.errors)
        self.assertNotIn("mean_vertex_error_m", result.metrics)
        self.assertLess(result.metrics["mean_surface_distance_m"], 0.02)

    def test_parameters_by_name_reach_their_stage(self):
        frames = clothtrack.read_sequence(os.path.join(self.data, "frames"))[:3]
        base = clothtrack.align(frames, template_frame=1, shape_frames=2, threads=1)
        # Patches must reach 5 m: none is kept, so no vertex has a correspondence and the fit
        # follows the nearest points alone.
        unmatched = clothtrack.align(frames, template_frame=1, shape_frames=2, threads=2, minimum_radius=5.0)
        self.assertGreater(np.abs(unmatched.positions - base.positions).max(), 1e-4)
        used = [a.GetPointData().GetArray("CorrespondenceUsed") for a in unmatched.aligned]
        self.assertEqual(sum(u.GetRange()[1] for k, u in enumerate(used) if k != 1), 0)

    def test_the_examples_run(self):
        examples = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python_wrapping", "examples")
        frames = os.path.join(self.data, "frames")
        npz = os.path.join(self.folder.name, "aligned.npz")
        out = subprocess.run([sys.executable, os.path.join(examples, "align_sequence.py"), frames, "--ground-truth",
                              os.path.join(self.data, "ground_truth"), "--template", "0", "-o", npz],
                             check=True, capture_output=True, text=True).stdout
        self.assertIn("template frame 0, %d frames" % FRAMES, out)
        saved = np.load(npz)
        self.assertEqual(saved["positions"].shape[0], FRAMES)
        self.assertLess(np.nanmean(saved["errors"][1:]), 0.03)
        vtp = os.path.join(self.folder.name, "chain.vtp")
        out = subprocess.run([sys.executable, os.path.join(examples, "filter_chain.py"), frames, vtp],
                             check=True, capture_output=True, text=True).stdout
        self.assertIn("wrote " + vtp, out)
        self.assertGreater(os.path.getsize(vtp), 10000)

    def test_bad_input_raises(self):
        with self.assertRaisesRegex(ValueError, "no frames"):
            clothtrack.align([])
        with self.assertRaisesRegex(RuntimeError, "does-not-exist"):
            clothtrack.align(os.path.join(self.data, "does-not-exist"))
        frames = clothtrack.read_sequence(os.path.join(self.data, "frames"))
        with self.assertRaisesRegex(ValueError, "template_frame 7"):
            clothtrack.align(frames, template_frame=7)
        with self.assertRaisesRegex(ValueError, "solver"):
            clothtrack.align(frames, solver="newton")
        with self.assertRaisesRegex(TypeError, "unknown keyword.*min_radius"):
            clothtrack.align(frames, min_radius=0.05)
        with self.assertRaisesRegex(ValueError, "threads"):
            clothtrack.align(frames, threads=-1)
        with self.assertRaisesRegex(ValueError, "ground truth has 3 frames"):
            clothtrack.align(frames, ground_truth=frames[:3])
        missing = os.path.join(self.data, "missing.vtp")
        with self.assertRaisesRegex(FileNotFoundError, "missing.vtp: no such body model file"):
            clothtrack.align(frames, model=["builtin", missing])
        with self.assertRaisesRegex(ValueError, "no body model"):
            clothtrack.align(frames, model=[])
        bogus = os.path.join(self.data, "bogus.vtp")
        with open(bogus, "w") as f:
            f.write("not a body model\n")
        with self.assertRaisesRegex(RuntimeError, "^body model: .*bogus.vtp: .*a body model is a VTP file"):
            clothtrack.align(frames, model=bogus)


if __name__ == "__main__":
    unittest.main()
