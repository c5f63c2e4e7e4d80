"""Sequence helpers: read a whole captured sequence and view it as numpy arrays."""

import re

from vtkmodules.util import numpy_support


def read_sequence(path, frame_rate=25.0, length_unit="m", up_axis="y"):
    """Read every frame of a sequence (folder, glob pattern, list file or single file).

    Returns a list of vtkPolyData, one per frame, in natural order of the file names.
    Raises RuntimeError with the reader's message when a frame cannot be read.
    """
    from . import ctMeshSequenceReader

    units = {"m": 0, "cm": 1, "mm": 2}
    axes = {"x": 0, "y": 1, "z": 2}
    if length_unit not in units:
        raise ValueError("length_unit must be one of m, cm, mm")
    if up_axis.lower() not in axes:
        raise ValueError("up_axis must be one of x, y, z")
    reader = ctMeshSequenceReader()
    reader.SetFileName(str(path))
    reader.SetFrameRate(frame_rate)
    reader.SetLengthUnit(units[length_unit])
    reader.SetUpAxis(axes[up_axis.lower()])
    errors = _ErrorCatcher(reader)
    reader.Update(1)
    sequence = reader.GetSequenceOutput()
    if errors.message or sequence is None or sequence.GetNumberOfBlocks() == 0:
        raise RuntimeError(errors.message or "%s: no frame could be read" % path)
    return [sequence.GetBlock(k) for k in range(sequence.GetNumberOfBlocks())]


def frames_as_numpy(frames):
    """(points n x 3, triangles m x 3) numpy arrays for each vtkPolyData in `frames`."""
    out = []
    for frame in frames:
        points = numpy_support.vtk_to_numpy(frame.GetPoints().GetData())
        conn = numpy_support.vtk_to_numpy(frame.GetPolys().GetConnectivityArray())
        out.append((points, conn.reshape(-1, 3)))
    return out


def _readable(message):
    """The filter's own words: VTK puts its source file, line and object address before them."""
    text = str(message).strip()
    if text.startswith("ERROR: In ") and "\n" in text:
        text = text.split("\n", 1)[1]
    return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", text)


class _ErrorCatcher:
    """Keeps the first error message an algorithm emits (instead of printing it), without VTK's
    source location."""

    def __init__(self, algorithm):
        from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

        self.message = ""

        def on_error(_obj, _event, message):
            if not self.message:
                self.message = _readable(message)

        on_error.CallDataType = VTK_STRING  # receive the message text, not a pointer
        algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
