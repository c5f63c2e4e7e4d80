"""A private virtual X display (Xvfb) for renders on machines without a screen.

Xvfb chooses the display number itself (-displayfd): the first number whose sockets are all free,
with no window between choosing a number and taking it. It runs with -noreset, so programs that
connect one after the other never meet a server in the middle of a reset. What it prints is kept
and shown when the command fails, to tell a lost display from a failing command.

A private display is only private if programs stay off the others: OpenMPI (linked by ParaView's
pvpython) loads hwloc, whose GL component opens every X display from :0 to :9 to list GPUs. When
another program's server shuts down during that probe, Xlib ends the process ("X connection to :0
broken"). The command's environment therefore turns that component off (HWLOC_COMPONENTS=-gl).

As a program, it runs a command under a display of its own and returns the command's exit code:

usage: python3 virtual_display.py [--size WxH] [--server-arg ARG ...] -- COMMAND [ARGS ...]

The file uses the standard library only, so it also runs by path without the package (the
pvpython tests run it so, with no PYTHONPATH).
"""
import contextlib
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile

STARTUP_SECONDS = 30.0
NO_DISPLAY_PROBE = "-gl"  # hwloc components to leave out: the GL one probes every X display


class VirtualDisplayError(RuntimeError):
    pass


class VirtualDisplay:
    """An Xvfb server for the lifetime of the object (use it in a `with` statement).

    display is the value for DISPLAY (":N"). The server does not reset when its last client
    leaves, so that programs connecting one after the other never meet a server mid-reset.
    """

    def __init__(self, size="1280x800", server_args=()):
        if not shutil.which("Xvfb"):
            raise VirtualDisplayError("renders need an X display or Xvfb (Debian package: xvfb)")
        self._log = tempfile.TemporaryFile()
        read_end, write_end = os.pipe()
        command = ["Xvfb", "-displayfd", str(write_end), "-screen", "0", size + "x24",
                   "-nolisten", "tcp", "-noreset"] + list(server_args)
        try:
            self._server = subprocess.Popen(command, pass_fds=(write_end,), stdin=subprocess.DEVNULL,
                                            stdout=self._log, stderr=self._log)
        finally:
            os.close(write_end)
        try:
            self.display = ":" + self._read_display_number(read_end)
        except VirtualDisplayError:
            self.close()
            raise
        finally:
            os.close(read_end)

    def _read_display_number(self, read_end):
        text = b""
        while not text.endswith(b"\n"):
            ready, _, _ = select.select([read_end], [], [], STARTUP_SECONDS)
            if not ready:
                raise VirtualDisplayError("Xvfb did not start: no display within %.0f s" % STARTUP_SECONDS)
            chunk = os.read(read_end, 32)
            if not chunk:  # the server exited: its last words say why
                lines = self.log_lines()
                raise VirtualDisplayError("Xvfb did not start: " + (lines[-1] if lines else "it exited"))
            text += chunk
        return text.decode().strip()

    def environment(self, base=None):
        """base (default: os.environ) with DISPLAY set to this server and hwloc's probe of the
        other displays turned off, for the programs run under it."""
        env = dict(os.environ if base is None else base, DISPLAY=self.display)
        components = [c for c in env.get("HWLOC_COMPONENTS", "").split(",") if c]
        if NO_DISPLAY_PROBE not in components:
            env["HWLOC_COMPONENTS"] = ",".join(components + [NO_DISPLAY_PROBE])
        return env

    def log_lines(self):
        """What the server printed so far."""
        self._log.seek(0)
        return self._log.read().decode(errors="replace").strip().splitlines()

    def state(self):
        """'running', or how the server ended (to tell a failed command from a lost display)."""
        code = self._server.poll()
        return "running" if code is None else "exited with code %d" % code

    def close(self):
        if self._server.poll() is None:
            self._server.terminate()
            try:
                self._server.wait(10)
            except subprocess.TimeoutExpired:
                self._server.kill()
                self._server.wait()
        self._log.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


@contextlib.contextmanager
def ensure_display(size="1280x800"):
    """Yields with DISPLAY set: the caller's own display when there is one, else a private one."""
    if os.environ.get("DISPLAY"):
        yield os.environ["DISPLAY"]
        return
    with VirtualDisplay(size) as display:
        os.environ["DISPLAY"] = display.display
        try:
            yield display.display
        finally:
            os.environ.pop("DISPLAY", None)


def _terminate(signum, frame):
    raise SystemExit(128 + signum)


def main(argv):
    size, server_args, args = "1280x800", [], list(argv[1:])
    while args and args[0] != "--":
        option = args.pop(0)
        if option in ("--size", "--server-arg") and args:
            value = args.pop(0)
            if option == "--size":
                size = value
            else:
                server_args.append(value)
        else:
            print(__doc__.strip(), file=sys.stderr)
            return 2
    if len(args) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    command = args[1:]
    # A test runner stops a test with SIGTERM: stop the command and the server with it.
    signal.signal(signal.SIGTERM, _terminate)
    try:
        with VirtualDisplay(size, server_args) as display:
            child = subprocess.Popen(command, env=display.environment())
            try:
                code = child.wait()
            finally:
                if child.poll() is None:
                    child.terminate()
                    child.wait()
            if code != 0:
                # A failed command may have lost its display: say how the server fared.
                print("virtual_display: the command exited with %d; Xvfb on %s %s" % (
                    code, display.display, display.state()), file=sys.stderr)
                for line in display.log_lines()[-10:]:
                    print("virtual_display: Xvfb: " + line, file=sys.stderr)
            return code
    except (VirtualDisplayError, OSError) as error:
        print("virtual_display: %s" % error, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
