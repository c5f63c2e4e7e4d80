"""The clothtrack Python package: import, read sequences, numpy views, errors."""

import os
import tempfile
import unittest

import clothtrack

SHARED = os.environ.get("CLOTHTRACK_SHARED_DATA", os.path.join(os.path.dirname(__file__), "../../../shared/data"))
TETRA = "v 0 {y} 0\nv 1 {y} 0\nv 0 {y}.5 1\nv 0 {y} 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"


def write_sequence(folder, count):
    for k in range(count):
        with open(os.path.join(folder, "tet_%d.obj" % k), "w") as f:
            f.write(TETRA.format(y=k))


class ReaderTest(unittest.TestCase):
    def test_classes_are_exposed(self):
        for name in ("ctMeshSequenceReader", "ctMeshSequenceWriter", "ctGeodesicDistance", "ctSurfaceTopology"):
            self.assertTrue(hasattr(clothtrack, name), name)

    def test_temporal_reading_and_numpy(self):
        with tempfile.TemporaryDirectory() as folder:
            write_sequence(folder, 12)
            reader = clothtrack.ctMeshSequenceReader()
            reader.SetFileName(folder)
            reader.SetFrameRate(4.0)
            reader.UpdateInformation()
            self.assertEqual(reader.GetNumberOfFrames(), 12)
            reader.UpdateTimeStep(10 / 4.0)
            frame = reader.GetOutput()
            self.assertAlmostEqual(frame.GetPoint(0)[1], 10.0)
            self.assertEqual(frame.GetFieldData().GetArray("FrameNumber").GetValue(0), 10)

            frames = clothtrack.read_sequence(folder)
            self.assertEqual(len(frames), 12)
            arrays = clothtrack.frames_as_numpy(frames)
            points, triangles = arrays[3]
            self.assertEqual(points.shape, (4, 3))
            self.assertEqual(triangles.shape, (4, 3))
            self.assertAlmostEqual(float(points[:, 1].min()), 3.0)

    def test_chains_with_vtk_filters(self):
        from vtkmodules.vtkFiltersCore import vtkTriangleFilter

        with tempfile.TemporaryDirectory() as folder:
            write_sequence(folder, 2)
            reader = clothtrack.ctMeshSequenceReader()
            reader.SetFileName(folder)
            topology = clothtrack.ctSurfaceTopology()
            triangles = vtkTriangleFilter()
            triangles.SetInputConnection(reader.GetOutputPort(0))
            topology.SetInputConnection(triangles.GetOutputPort())
            topology.Update()
            genus = topology.GetOutput().GetFieldData().GetArray("ComponentGenus")
            self.assertEqual(genus.GetValue(0), 0)

    def test_bad_input_raises_with_file_name(self):
        with tempfile.TemporaryDirectory() as folder:
            bad = os.path.join(folder, "bad_0.obj")
            with open(bad, "w") as f:
                f.write("v 0 0 0\nv 1 0 0\nf 1 2 3\n")
            with self.assertRaises(RuntimeError) as ctx:
                clothtrack.read_sequence(folder)
            self.assertIn("bad_0.obj", str(ctx.exception))
            self.assertIn("out of range", str(ctx.exception))
            with self.assertRaises(RuntimeError):
                clothtrack.read_sequence(os.path.join(folder, "missing"))

    def test_vlasic_samba_has_175_frames(self):
        samba = os.path.join(SHARED, "vlasic-samba")
        if not os.path.isdir(samba):
            self.skipTest("shared data not found at %s" % samba)
        reader = clothtrack.ctMeshSequenceReader()
        reader.SetFileName(samba)
        reader.UpdateInformation()
        self.assertEqual(reader.GetNumberOfFrames(), 175)


if __name__ == "__main__":
    unittest.main()
