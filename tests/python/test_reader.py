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
        for name in ("ctMeshSequenceReader", "ctMeshSequenceWriter", "ctGeodesicDistance", "ctSurfaceTopology",
                     "ctModelChoice"):
            self.assertTrue(hasattr(clothtrack, name), name)

    def test_the_version_is_the_apps(self):
        app = os.environ.get("CLOTHTRACK_APP")
        if not app:
            self.skipTest("CLOTHTRACK_APP is not set")
        import subprocess
        out = subprocess.run([app, "--version"], check=True, capture_output=True, text=True).stdout
        self.assertEqual(out.split(), ["clothtrack", clothtrack.__version__])
        self.assertRegex(clothtrack.__version__, r"^\d+\.\d+\.\d+$")

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

    def test_files_that_crashed_vtk_raise(self):
        # Legacy VTK with the 5.x cell layout under a 4.2 version line, and an XML file with a
        # negative point count: both killed the interpreter inside VTK's readers.
        with tempfile.TemporaryDirectory() as folder:
            legacy = os.path.join(folder, "legacy_0.vtk")
            with open(legacy, "w") as f:
                f.write("# vtk DataFile Version 4.2\ntet\nASCII\nDATASET POLYDATA\n"
                        "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n"
                        "POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\n"
                        "CONNECTIVITY vtktypeint64\n0 1 2 0 1 3 0 2 3 1 2 3\n")
            self.assertEqual(clothtrack.read_sequence(legacy)[0].GetNumberOfCells(), 4)
            xml = os.path.join(folder, "negative_0.vtp")
            with open(xml, "w") as f:
                f.write('<VTKFile type="PolyData" version="1.0"><PolyData>'
                        '<Piece NumberOfPoints="-1" NumberOfPolys="1"></Piece>'
                        '</PolyData></VTKFile>')
            with self.assertRaises(RuntimeError) as ctx:
                clothtrack.read_sequence(xml)
            self.assertIn("negative_0.vtp", str(ctx.exception))
            self.assertIn("NumberOfPoints", str(ctx.exception))

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
