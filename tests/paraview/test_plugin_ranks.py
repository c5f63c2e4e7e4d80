"""The plugin under pvbatch --mpi with 2 processes: every stage's output holds what it holds in one
process (no stage computed on both, nothing shown twice), the per-frame errors and the aligned
positions are the same to the bit, and the plugin's writer writes the same files once.

usage: python3 test_plugin_ranks.py MPIEXEC PVBATCH PARAVIEW_PYTHONPATH PLUGIN CLOTHTRACK_APP SCRATCH
Run under a virtual display (pvbatch renders nothing here but needs one to start).
"""
import filecmp
import json
import os
import shutil
import subprocess
import sys

mpiexec, pvbatch, pythonpath, plugin, app, scratch = sys.argv[1:7]
probe = os.path.join(os.path.dirname(os.path.abspath(__file__)), "plugin_ranks_probe.py")


def run_probe(ranks, out):
    """The probe's JSON line from `ranks` processes (1: pvbatch alone, without MPI)."""
    command = [pvbatch, "--force-offscreen-rendering", probe, plugin, capture, os.path.join(out, "aligned.pvd")]
    if ranks > 1:
        command = [mpiexec, "--oversubscribe", "-np", str(ranks), "-x", "PYTHONPATH", "-x", "DISPLAY",
                   command[0], "--mpi"] + command[1:]
    log = out + ".log"
    with open(log, "w") as f:
        code = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT, timeout=900).returncode
    text = open(log).read()
    if code != 0:
        sys.exit("FAIL: %d process(es) exited with %d; see %s" % (ranks, code, log))
    if "ERR|" in text or "Error" in text:
        sys.exit("FAIL: %d process(es) reported an error; see %s" % (ranks, log))
    lines = [l for l in text.splitlines() if l.startswith("PROBE ")]
    if len(lines) != 1:
        sys.exit("FAIL: %d process(es) printed %d probe lines; see %s" % (ranks, len(lines), log))
    return json.loads(lines[0][len("PROBE "):])


os.environ.update(PYTHONPATH=pythonpath, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
capture = os.path.join(scratch, "synth")
subprocess.run([app, "synth", "--preset", "skirt-turn", "--frames", "4", "--seed", "3", "--voxel", "0.02",
                "-o", capture],
               check=True, stdout=subprocess.DEVNULL)
one = run_probe(1, os.path.join(scratch, "one"))
two = run_probe(2, os.path.join(scratch, "two"))
if one["ranks"] != 1 or two["ranks"] != 2:
    sys.exit("FAIL: ran on %d and %d processes, expected 1 and 2" % (one["ranks"], two["ranks"]))
for key in sorted(one["totals"]):
    if one["totals"][key] != two["totals"].get(key):
        sys.exit("FAIL: %s holds %s (points, cells, rows) in one process, %s over two"
                 % (key, one["totals"][key], two["totals"].get(key)))
if len(one["errors"]) != 4 or one["errors"] != two["errors"]:
    sys.exit("FAIL: per-frame errors %s in one process, %s in two" % (one["errors"], two["errors"]))
if one["checksum"] != two["checksum"]:
    sys.exit("FAIL: aligned positions differ between one process and two")
written = sorted(os.listdir(os.path.join(scratch, "one", "aligned")))
if len(written) != 4 or written != sorted(os.listdir(os.path.join(scratch, "two", "aligned"))):
    sys.exit("FAIL: the writer wrote %s in one process" % written)
for name in written + [os.path.join("..", "aligned.pvd")]:
    a, b = (os.path.join(scratch, run, "aligned", name) for run in ("one", "two"))
    if not filecmp.cmp(a, b, shallow=False):
        sys.exit("FAIL: %s differs between one process and two" % name)
print("%d outputs, %d frames' errors and files identical with 2 processes" % (len(one["totals"]), len(written)))
print("plugin ranks test passed")
