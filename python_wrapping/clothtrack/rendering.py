"""Offscreen rendering helpers (VTK needs an X display here: run under xvfb-run when there is none)."""

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


def _connect(algorithm, source):
    if hasattr(source, "GetProducer"):
        algorithm.SetInputConnection(source)
    else:
        algorithm.SetInputData(source)
