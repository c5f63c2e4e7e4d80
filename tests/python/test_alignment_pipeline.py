"""Stages 1 to 3 chained from Python on a synthetic skirt capture: body fit and landmarks, patch
correspondence, template fit, then the alignment error. The aligned template is checked against the
ground truth that the capture's source map gives for every template vertex, and ctAlignmentError
against that same check."""

import unittest

import numpy as np
import clothtrack
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline

FRAMES = 3
FRAME_RATE = 10.0  # frames 0.1 s apart: the skirt turns visibly between them


def as_numpy(array):
    return numpy_support.vtk_to_numpy(array).copy()


def triangles(poly):
    return as_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)


class AlignmentPipelineTest(unittest.TestCase):
    def test_skirt_sequence_is_aligned(self):
        source = clothtrack.ctSyntheticCapture()
        source.SetPreset("skirt-turn")
        source.SetNumberOfFrames(FRAMES)
        source.SetFrameRate(FRAME_RATE)
        sequence = vtkMultiBlockDataSet()
        truth_sequence = vtkMultiBlockDataSet()
        truths, sources = [], []
        for k in range(FRAMES):
            time = k / FRAME_RATE
            source.UpdateTimeStep(time)
            truths.append(as_numpy(source.GetOutput().GetPoints().GetData()))
            truth_faces = triangles(source.GetOutput())
            truth_frame = source.GetOutput().NewInstance()
            truth_frame.DeepCopy(source.GetOutput())
            truth_sequence.SetBlock(k, truth_frame)
            source.GetOutputInformation(1).Set(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP(), time)
            source.Update(1)
            frame = source.GetCaptureOutput().NewInstance()
            frame.DeepCopy(source.GetCaptureOutput())
            data = frame.GetPointData()
            sources.append((as_numpy(data.GetArray("SourceFace")), as_numpy(data.GetArray("SourceBarycentric")),
                            as_numpy(data.GetArray("SourceDistance"))))
            sequence.SetBlock(k, frame)

        body = clothtrack.ctBodyFit()
        body.SetInputData(sequence)
        body.SetShapeFrames(2)
        correspondence = clothtrack.ctPatchCorrespondence()
        correspondence.SetInputData(0, sequence)
        correspondence.SetInputConnection(1, body.GetOutputPort(1))
        fit = clothtrack.ctTemplateFit()
        fit.SetInputData(0, sequence)
        fit.SetInputConnection(1, correspondence.GetOutputPort(0))
        fit.SetInputConnection(2, body.GetOutputPort(1))  # landmarks: starts follow their motion
        error_filter = clothtrack.ctAlignmentError()
        error_filter.SetInputConnection(0, fit.GetOutputPort(0))
        error_filter.SetInputData(1, truth_sequence)
        error_filter.Update()

        j = correspondence.GetChosenFrame()
        aligned = fit.GetOutputDataObject(0)
        self.assertEqual(aligned.GetNumberOfBlocks(), FRAMES)
        face, bary, distance = sources[j]
        has_truth = distance <= 0.03
        corners = truth_faces[face[has_truth]]
        n = aligned.GetBlock(j).GetNumberOfPoints()
        for k in range(FRAMES):
            block = aligned.GetBlock(k)
            self.assertEqual(block.GetNumberOfPoints(), n)
            points = as_numpy(block.GetPoints().GetData())[has_truth]
            truth = (truths[k][corners] * bary[has_truth][:, :, None]).sum(1)
            error = np.linalg.norm(points - truth, axis=1)
            # The template left where it is, for comparison (measured: 3.2 and 4.9 cm against
            # 1.9 and 2.6 cm fitted).
            still = np.linalg.norm(as_numpy(aligned.GetBlock(j).GetPoints().GetData())[has_truth] - truth, axis=1)
            self.assertLess(error.mean(), 0.05, "frame %d" % k)
            if k != j:
                self.assertLess(error.mean(), still.mean() - 0.01, "frame %d" % k)
            self.assertGreater((error < 0.10).mean(), 0.9, "frame %d" % k)
            surface = as_numpy(block.GetPointData().GetArray("SurfaceDistance"))
            self.assertLess(np.median(surface), 0.01)
            # The filter ties template vertices to the truth as the source map does (closest point,
            # 3 cm at most): the same errors.
            table = error_filter.GetFrameErrorOutput()
            self.assertAlmostEqual(table.GetValueByName(k, "Mean").ToDouble(), error.mean(), places=4)
            with_error = as_numpy(error_filter.GetOutputDataObject(0).GetBlock(k).GetPointData().GetArray("Error"))
            self.assertEqual(int(np.isfinite(with_error).sum()), int(has_truth.sum()))
        summary = fit.GetSummaryOutput()
        self.assertEqual(summary.GetNumberOfRows(), FRAMES)
        self.assert_unplaced_frame_is_doubtful(sequence, body, correspondence, j)

    def assert_unplaced_frame_is_doubtful(self, sequence, body, correspondence, j):
        """A frame whose body is doubtful and unlike its predecessor's had nothing to start it:
        its confidence is halved, whatever it measures."""
        bodies = vtkMultiBlockDataSet()
        bodies.DeepCopy(body.GetOutputDataObject(0))
        k = (j + 1) % FRAMES
        fields = bodies.GetBlock(k).GetFieldData()
        self.assertEqual(fields.GetArray("ContinuesPrevious").GetTuple1(0), 1)
        fit = clothtrack.ctTemplateFit()
        fit.SetInputData(0, sequence)
        fit.SetInputConnection(1, correspondence.GetOutputPort(0))
        fit.SetInputData(3, bodies)
        fit.Update()
        confident = as_numpy(fit.GetSummaryOutput().GetColumnByName("Confidence"))
        self.assertTrue(np.all(confident == 1.0), confident)
        fields.GetArray("FitStatus").SetTuple1(0, 1)  # poor
        fields.GetArray("ContinuesPrevious").SetTuple1(0, 0)
        bodies.Modified()
        fit.Update()
        confidence = as_numpy(fit.GetSummaryOutput().GetColumnByName("Confidence"))
        self.assertEqual(confidence[k], 0.5)
        self.assertTrue(np.all(np.delete(confidence, k) == 1.0), confidence)


if __name__ == "__main__":
    unittest.main()
