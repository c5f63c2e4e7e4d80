"""The body model from Python: shape, pose and landmarks as numpy arrays."""

import unittest

import numpy as np
import clothtrack
from vtkmodules.util import numpy_support


def body_points(source, port=0):
    source.Update()
    return numpy_support.vtk_to_numpy(source.GetOutputDataObject(port).GetPoints().GetData())


class BodyModelTest(unittest.TestCase):
    def test_shape_changes_the_body_and_pose_moves_the_arm(self):
        mean = clothtrack.ctBodyModelSource()
        rest = body_points(mean).copy()
        height = rest[:, 1].max() - rest[:, 1].min()
        self.assertGreater(height, 1.55)
        self.assertLess(height, 1.90)

        tall = clothtrack.ctBodyModelSource()
        tall.SetShapeCoefficient(0, 2.0)
        shaped = body_points(tall)
        self.assertEqual(shaped.shape, rest.shape)
        self.assertGreater(np.abs(shaped - rest).max(), 0.02)

        raised = clothtrack.ctBodyModelSource()
        raised.SetJointRotation(7, 0.0, 0.0, 1.0)  # left shoulder up
        posed = body_points(raised)
        moved = np.linalg.norm(posed - rest, axis=1) > 0.02
        self.assertTrue(np.all(rest[moved, 0] > 0.0))  # only the left arm side moves
        self.assertGreater(posed[:, 1].max(), rest[:, 1].max() - 0.01)

    def test_forty_landmarks_with_names(self):
        source = clothtrack.ctBodyModelSource()
        landmarks = body_points(source, 1)
        self.assertEqual(landmarks.shape, (40, 3))
        names = source.GetLandmarksOutput().GetPointData().GetAbstractArray("LandmarkName")
        all_names = {names.GetValue(k) for k in range(40)}
        for expected in ("forehead", "left_wrist", "right_heel", "belly"):
            self.assertIn(expected, all_names)

    def test_model_file_round_trip_through_the_reader(self):
        import os
        import tempfile
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "model.vtp")
            app = os.environ.get("CLOTHTRACK_APP")
            # The reader checks the file: an ordinary mesh is refused.
            plain = os.path.join(folder, "plain.vtp")
            body = clothtrack.ctBodyModelSource()  # must outlive the connection
            writer = vtkXMLPolyDataWriter()
            writer.SetInputConnection(body.GetOutputPort(0))
            writer.SetFileName(plain)
            writer.Write()
            reader = clothtrack.ctBodyModelReader()
            reader.SetFileName(plain)
            reader.Update()
            self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)
            if app:
                import subprocess
                subprocess.run([app, "body-model", "-o", path], check=True, capture_output=True)
                reader.SetFileName(path)
                reader.Update()
                self.assertGreater(reader.GetOutput().GetNumberOfPoints(), 5000)
                self.assertGreaterEqual(reader.GetNumberOfShapeComponents(), 10)


if __name__ == "__main__":
    unittest.main()
