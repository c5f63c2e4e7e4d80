#!/usr/bin/env python3
"""Screenshot of the ParaView GUI with the ClothTrack plugin loaded and a state file open, taken on a
virtual display (for the docs, and to try the plugin as a user would).

usage: paraview_gui_screenshot.py PLUGIN_DIR OUT.png [--state STATE.pvsm] [--events EVENTS.xml]
                                  [--wait SECONDS] [--size WxH]

Starts Xvfb with its framebuffer in a file, runs `paraview` with the plugin found through
PV_PLUGIN_PATH (and the state, and a recorded event script played by ParaView's --test-script, e.g.
scripts/paraview_filters_menu.xml, which opens Filters > ClothTrack), waits, and converts the
framebuffer (XWD) to PNG.
"""
import argparse
import importlib.util
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time

from PIL import Image

# The package's virtual display, loaded by path: the package itself needs the built VTK modules.
_spec = importlib.util.spec_from_file_location(
    "virtual_display", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python_wrapping",
                                    "clothtrack", "virtual_display.py"))
virtual_display = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(virtual_display)


def read_xwd(path):
    with open(path, "rb") as f:
        data = f.read()
    fields = struct.unpack(">25I", data[:100])
    header_size, width, height = fields[0], fields[4], fields[5]
    byte_order, bits_per_pixel, bytes_per_line, ncolors = fields[7], fields[11], fields[12], fields[19]
    if bits_per_pixel != 32:
        raise RuntimeError("%s: %d bits per pixel, expected 32" % (path, bits_per_pixel))
    start = header_size + 12 * ncolors
    raw = data[start:start + bytes_per_line * height]
    mode = "BGRX" if byte_order == 0 else "XRGB"
    return Image.frombuffer("RGB", (width, height), raw, "raw", mode, bytes_per_line, 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("plugin_dir")
    parser.add_argument("out")
    parser.add_argument("--state", help="a ParaView state file to open")
    parser.add_argument("--events", help="a ParaView event script (XML) to play once started")
    parser.add_argument("--wait", type=float, default=60.0, help="seconds to let ParaView load and render")
    parser.add_argument("--size", default="1280x800")
    args = parser.parse_args()
    for tool in ("Xvfb", "paraview"):
        if not shutil.which(tool):
            sys.exit("paraview_gui_screenshot: %s is not installed" % tool)
    with tempfile.TemporaryDirectory() as fbdir:
        with virtual_display.VirtualDisplay(args.size, ["-fbdir", fbdir]) as xvfb:
            # Default settings (--dr), and a private home so that the user's own are left alone. A
            # warning opens the message window over the view: use data that reads without one.
            home = os.path.join(fbdir, "home")
            os.makedirs(home)
            env = xvfb.environment(dict(os.environ, HOME=home, PV_PLUGIN_PATH=os.path.abspath(args.plugin_dir)))
            env.pop("PYTHONPATH", None)
            width, height = args.size.split("x")
            command = ["paraview", "--dr", "-geometry", "%sx%s+0+0" % (width, height)]
            if args.state:
                command.append("--state=" + os.path.abspath(args.state))
            if args.events:
                command.append("--test-script=" + os.path.abspath(args.events))
            gui = subprocess.Popen(command, env=env,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(args.wait)
            if gui.poll() is not None:
                sys.exit("paraview_gui_screenshot: paraview exited with %d" % gui.returncode)
            read_xwd(os.path.join(fbdir, "Xvfb_screen0")).save(args.out)
            gui.terminate()
            gui.wait(10)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
