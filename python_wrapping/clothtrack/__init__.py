"""ClothTrack: temporal alignment of captured human motion in wide clothing.

Every stage is a VTK algorithm and chains with VTK's own filters::

    import clothtrack
    reader = clothtrack.ctMeshSequenceReader()
    reader.SetFileName("frames/")
    reader.UpdateInformation()
    print(reader.GetNumberOfFrames())

or run the whole pipeline in one call::

    result = clothtrack.align("frames/", ground_truth="ground_truth/")
    print(result.metrics["mean_vertex_error_m"], result.positions.shape)
"""

# VTK's own modules must be loaded before the wrapped ClothTrack modules that derive from them.
from vtkmodules import vtkCommonCore as _vtkCommonCore  # noqa: F401
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel  # noqa: F401
from vtkmodules import vtkCommonExecutionModel as _vtkCommonExecutionModel  # noqa: F401

from .ctReaders import *  # noqa: F401,F403
from .ctFilters import *  # noqa: F401,F403
from .sequence import frames_as_numpy, read_sequence  # noqa: F401
from .pipeline import Alignment, align  # noqa: F401

from ._version import __version__  # noqa: F401,E402  (written by CMake: the project's version)
