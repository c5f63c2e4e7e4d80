"""ctBodyFit from Python: the body under a synthetic skirt, chained after VTK's own objects."""

import unittest

import numpy as np
import clothtrack
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline


class BodyFitTest(unittest.TestCase):
    def test_body_under_a_skirt(self):
        source = clothtrack.ctSyntheticCapture()
        source.SetPreset("skirt-turn")
        source.SetNumberOfFrames(3)
        sequence = vtkMultiBlockDataSet()
        truths = []
        for k in range(3):
            source.UpdateTimeStep(k / 25.0)
            truths.append(numpy_support.vtk_to_numpy(source.GetOutput().GetPoints().GetData()).copy())
            source.GetOutputInformation(1).Set(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP(), k / 25.0)
            source.Update(1)
            frame = source.GetCaptureOutput().NewInstance()
            frame.DeepCopy(source.GetCaptureOutput())
            sequence.SetBlock(k, frame)

        fit = clothtrack.ctBodyFit()
        fit.SetInputData(sequence)
        fit.SetShapeFrames(2)
        fit.Update()
        bodies = fit.GetOutputDataObject(0)
        self.assertEqual(bodies.GetNumberOfBlocks(), 3)
        status = numpy_support.vtk_to_numpy(fit.GetStatusOutput().GetColumnByName("Status"))
        self.assertTrue((status == 0).all())
        for k in range(3):
            body = numpy_support.vtk_to_numpy(bodies.GetBlock(k).GetPoints().GetData())
            # The body lies under the clothed ground truth: every body vertex is near it.
            truth = truths[k]
            sample = body[::50]
            nearest = np.sqrt(((sample[:, None, :] - truth[None, ::5, :]) ** 2).sum(-1)).min(1)
            self.assertLess(np.median(nearest), 0.04)
            found = fit.GetLandmarksOutput().GetBlock(k).GetFieldData().GetArray("FoundFraction").GetValue(0)
            self.assertGreater(found, 0.75)

    def test_empty_sequence_is_an_error(self):
        fit = clothtrack.ctBodyFit()
        fit.SetInputData(vtkMultiBlockDataSet())
        from clothtrack.sequence import _ErrorCatcher

        errors = _ErrorCatcher(fit)
        fit.Update()
        self.assertIn("no frame", errors.message)


if __name__ == "__main__":
    unittest.main()
