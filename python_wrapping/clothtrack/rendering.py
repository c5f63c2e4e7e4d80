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
