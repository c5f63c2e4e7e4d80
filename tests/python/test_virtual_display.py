"""clothtrack.virtual_display: private Xvfb servers that never share a display number, renders on
them, the command's exit code, and a readable error without Xvfb."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from clothtrack import virtual_display

SCRIPT = virtual_display.__file__

# Renders a red background offscreen and prints the centre pixel.
RENDER = """
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
renderer = vtkRenderer()
renderer.SetBackground(1, 0, 0)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(32, 32)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
print("pixel", [int(grab.GetOutput().GetScalarComponentAsDouble(16, 16, 0, c)) for c in range(3)])
"""


@unittest.skipUnless(shutil.which("Xvfb"), "Xvfb is not installed (Debian package: xvfb)")
class VirtualDisplayTest(unittest.TestCase):
    def test_servers_side_by_side_get_their_own_numbers(self):
        with virtual_display.VirtualDisplay("320x240") as first, virtual_display.VirtualDisplay("320x240") as second:
            self.assertRegex(first.display, r"^:\d+$")
            self.assertNotEqual(first.display, second.display)
            for display in (first, second):
                self.assertTrue(os.path.exists("/tmp/.X11-unix/X" + display.display[1:]), display.display)
        self.assertIsNotNone(first._server.poll())
        self.assertIsNotNone(second._server.poll())

    def test_command_renders_and_its_exit_code_is_returned(self):
        env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        result = subprocess.run([sys.executable, SCRIPT, "--size", "320x240", "--", sys.executable, "-c", RENDER],
                                env=env, capture_output=True, text=True, timeout=120)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("pixel [255, 0, 0]", result.stdout)
        result = subprocess.run([sys.executable, SCRIPT, "--", sys.executable, "-c", "import sys; sys.exit(7)"],
                                env=env, timeout=60)
        self.assertEqual(result.returncode, 7)

    def test_command_stays_off_the_other_displays(self):
        # hwloc (loaded by OpenMPI in pvpython) would otherwise open :0 to :9, and a test whose
        # server shuts down meanwhile would end the command.
        show = "import os; print(os.environ['DISPLAY'], os.environ['HWLOC_COMPONENTS'])"
        env = dict(os.environ, HWLOC_COMPONENTS="no_os")
        env.pop("DISPLAY", None)
        result = subprocess.run([sys.executable, SCRIPT, "--", sys.executable, "-c", show],
                                env=env, capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        display, components = result.stdout.split()
        self.assertRegex(display, r"^:\d+$")
        self.assertEqual(components, "no_os,-gl")

    def test_ensure_display_keeps_an_existing_display(self):
        saved = os.environ.get("DISPLAY")
        try:
            os.environ["DISPLAY"] = ":4242"
            with virtual_display.ensure_display() as display:
                self.assertEqual(display, ":4242")
            os.environ.pop("DISPLAY")
            with virtual_display.ensure_display() as display:
                self.assertEqual(os.environ["DISPLAY"], display)
            self.assertNotIn("DISPLAY", os.environ)
        finally:
            if saved is None:
                os.environ.pop("DISPLAY", None)
            else:
                os.environ["DISPLAY"] = saved


class VirtualDisplayErrorTest(unittest.TestCase):
    def test_without_xvfb_the_error_says_what_to_install(self):
        with tempfile.TemporaryDirectory() as empty:
            saved = os.environ["PATH"]
            os.environ["PATH"] = empty
            try:
                with self.assertRaisesRegex(virtual_display.VirtualDisplayError, "Xvfb"):
                    virtual_display.VirtualDisplay()
            finally:
                os.environ["PATH"] = saved

    def test_a_bad_server_option_is_reported(self):
        if not shutil.which("Xvfb"):
            self.skipTest("Xvfb is not installed (Debian package: xvfb)")
        with self.assertRaisesRegex(virtual_display.VirtualDisplayError, "Xvfb did not start"):
            virtual_display.VirtualDisplay(server_args=["-no-such-option"])

    def test_usage_without_a_command(self):
        result = subprocess.run([sys.executable, SCRIPT, "--size", "320x240"], capture_output=True, text=True)
        self.assertEqual(result.returncode, 2)
        self.assertIn("usage", result.stderr)


if __name__ == "__main__":
    unittest.main()
