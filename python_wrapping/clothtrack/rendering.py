"""Offscreen rendering helpers (VTK needs an X display here: without one, render inside
clothtrack.virtual_display.ensure_display())."""

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)


def offscreen_window(width, height):
    """A render window that draws offscreen, at the given size in pixels."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    return window


def save_png(window, path):
    """Render `window` and write it to `path` as PNG."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def colour_actor(source, colour, opacity=1.0, smooth_normals=False):
    """An actor drawing `source` (a vtkPolyData or an algorithm output port) in one colour.

    smooth_normals adds vertex normals first (meshes read from files often have none)."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    mapper = vtkPolyDataMapper()
    if smooth_normals:
        normals = vtkPolyDataNormals()
        normals.SplittingOff()
        _connect(normals, source)
        source = normals.GetOutputPort()
    _connect(mapper, source)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    actor.GetProperty().SetOpacity(opacity)
    return actor


def colour_field_actor(mesh, rgb):
    """An actor drawing vtkPolyData `mesh` with one RGB colour per vertex (`rgb`: vertices x 3,
    0-255), smooth-shaded: a colour field such as the correspondence images use."""
    import numpy as np
    from vtkmodules.util import numpy_support
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    data = vtkPolyData()
    data.ShallowCopy(mesh)
    colours = numpy_support.numpy_to_vtk(np.ascontiguousarray(rgb, dtype=np.uint8), deep=1)
    colours.SetName("Colour")
    data.GetPointData().SetScalars(colours)
    normals = vtkPolyDataNormals()
    normals.SplittingOff()
    normals.SetInputData(data)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetColorModeToDirectScalars()
    mapper.SetScalarModeToUsePointData()
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def _connect(algorithm, source):
    if hasattr(source, "GetProducer"):
        algorithm.SetInputConnection(source)
    else:
        algorithm.SetInputData(source)
