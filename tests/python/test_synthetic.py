"""ctSyntheticCapture from Python: ground truth keeps its connectivity, captures do not."""

import unittest

import numpy as np
import clothtrack
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline


class SyntheticCaptureTest(unittest.TestCase):
    def test_truth_and_capture_over_time(self):
        source = clothtrack.ctSyntheticCapture()
        source.SetPreset("skirt-turn")
        source.SetNumberOfFrames(4)
        source.SetFrameRate(10.0)
        truth_counts, capture_counts = set(), set()
        first = None
        for k in range(4):
            source.UpdateTimeStep(k / 10.0)  # port 0
            truth = source.GetOutput()
            points = numpy_support.vtk_to_numpy(truth.GetPoints().GetData()).copy()
            truth_counts.add(truth.GetNumberOfPoints())
            if first is None:
                first = points
            self.assertEqual(truth.GetFieldData().GetArray("FrameIndex").GetValue(0), k)
            garment = numpy_support.vtk_to_numpy(truth.GetPointData().GetArray("IsGarment"))
            self.assertGreater(garment.sum(), 1000)
            # The capture port at the same time.
            source.GetOutputInformation(1).Set(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP(), k / 10.0)
            source.Update(1)
            capture = source.GetCaptureOutput()
            capture_counts.add(capture.GetNumberOfPoints())
            distance = numpy_support.vtk_to_numpy(capture.GetPointData().GetArray("SourceDistance"))
            self.assertLess(np.median(distance), 0.015)
        self.assertEqual(len(truth_counts), 1)      # one connectivity
        self.assertGreater(len(capture_counts), 1)  # re-meshed every frame
        self.assertGreater(np.abs(points - first).max(), 0.05)  # the body turned

    def test_unknown_preset_is_an_error(self):
        from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

        messages = []

        def on_error(_obj, _event, message):
            messages.append(message)

        on_error.CallDataType = VTK_STRING
        source = clothtrack.ctSyntheticCapture()
        source.AddObserver(vtkCommand.ErrorEvent, on_error)
        source.SetPreset("kilt-jog")
        source.Update()
        self.assertTrue(any("unknown preset 'kilt-jog'" in m for m in messages), messages)


if __name__ == "__main__":
    unittest.main()
