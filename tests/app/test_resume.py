"""clothtrack align killed with SIGKILL at several points, resumed each time, ends with the
aligned frames and metrics of a run that was never stopped, bit for bit. The stopped runs keep no
frame in memory (--frame-memory 0: every frame is read again from its copy in the work folder
whenever a stage needs it), the uninterrupted one keeps them all.

Usage: test_resume.py APP WORK. The run-describing metrics (timings, memory, what was reused)
are the only ones allowed to differ.
"""
import filecmp
import json
import os
import shutil
import signal
import subprocess
import sys
import time

RUN_DESCRIBING = ("seconds_total", "seconds_per_frame", "seconds_per_fitted_frame",
                  "stage_seconds", "peak_rss_mb", "resumed_frames", "reused_correspondence_frames",
                  "reused_landmark_frames", "frame_memory_mb", "frame_reads", "frames_kept_on_disk",
                  "stage_peak_rss_mb", "rank_stage_seconds")


def align(app, synth, out, streamed=False):
    return [app, "align", os.path.join(synth, "frames"), "--ground-truth",
            os.path.join(synth, "ground_truth"), "-o", out, "--no-report", "--threads", "2"] + (
                ["--frame-memory", "0"] if streamed else [])


def run_until(command, log, stop_when, timeout=600):
    """Starts `command`; kills it with SIGKILL once stop_when() holds. Returns whether it was
    killed (False: it ended first, with exit code 0)."""
    with open(log, "ab") as out:
        process = subprocess.Popen(command, stdout=out, stderr=out)
        start = time.monotonic()
        while process.poll() is None:
            if stop_when(time.monotonic() - start):
                process.send_signal(signal.SIGKILL)
                process.wait()
                return True
            if time.monotonic() - start > timeout:
                process.kill()
                sys.exit(f"align did not end within {timeout} s")
            time.sleep(0.02)
    if process.returncode != 0:
        sys.exit(f"align failed with exit code {process.returncode}; see {log}")
    return False


def exists(path):
    return lambda elapsed: os.path.exists(path)


def main():
    app, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    synth = os.path.join(work, "synth")
    subprocess.run([app, "synth", "--preset", "shirt-armraise", "--frames", "6", "--seed", "5",
                    "--voxel", "0.02", "-o", synth], check=True, stdout=subprocess.DEVNULL)
    reference, resumed = os.path.join(work, "reference"), os.path.join(work, "resumed")
    started = time.monotonic()
    run_until(align(app, synth, reference), os.path.join(work, "reference.log"), lambda t: False)
    whole = time.monotonic() - started
    metrics = json.load(open(os.path.join(reference, "metrics.json")))
    fitted = [k for k in range(6) if k != metrics["template_frame"]]

    def aligned_at_least(count):
        folder = os.path.join(resumed, "aligned")
        return lambda elapsed: os.path.isdir(folder) and len(
            [f for f in os.listdir(folder) if f.endswith(".vtp")]) >= count

    # In the body fit, in the correspondences, after the first fitted frame (the template frame
    # is written first), and in the middle of the fit; each run resumes from what the ones
    # before it left.
    stops = [("the body fit", lambda t: t > 0.15 * whole),
             ("the correspondences",
              exists(os.path.join(resumed, "work", "correspondence", f"frame_{fitted[2]:04d}.bin"))),
             ("the first fitted frame", aligned_at_least(2)),
             ("the fit", aligned_at_least(4))]
    log = os.path.join(work, "resumed.log")
    for name, stop in stops:
        if not run_until(align(app, synth, resumed, True), log, stop):
            sys.exit(f"align ended before it could be stopped in {name}")
        print(f"stopped in {name}")
    run_until(align(app, synth, resumed, True), log, lambda t: False)

    for k in range(6):
        name = f"aligned_{k:04d}.vtp"
        if not filecmp.cmp(os.path.join(reference, "aligned", name),
                           os.path.join(resumed, "aligned", name), shallow=False):
            sys.exit(f"{name} differs from the uninterrupted run's")
    again = json.load(open(os.path.join(resumed, "metrics.json")))
    differing = sorted(key for key in set(metrics) | set(again)
                       if key not in RUN_DESCRIBING and metrics.get(key) != again.get(key))
    if differing:
        sys.exit("metrics differ from the uninterrupted run's: " + ", ".join(differing))
    if again["resumed_frames"] < 2 or again["reused_landmark_frames"] != 6:
        sys.exit(f"the last run resumed {again['resumed_frames']} frames (expected at least 2) "
                 f"and reused the landmarks of {again['reused_landmark_frames']} (expected 6)")
    if not again["frames_kept_on_disk"] or metrics["frames_kept_on_disk"]:
        sys.exit("the stopped runs were to keep their frames on disk, the reference in memory")
    if again["frame_reads"] < 6 or metrics["frame_reads"] != 0:
        sys.exit(f"frames read again: {again['frame_reads']} streamed (expected at least 6), "
                 f"{metrics['frame_reads']} in memory (expected 0)")
    if os.path.exists(os.path.join(resumed, "work", "frames")):
        sys.exit("the frames' copies were left in the work folder")
    leftovers = [f for _, _, files in os.walk(resumed) for f in files if f.endswith(".part")]
    if leftovers or os.path.exists(os.path.join(resumed, "fit_state")):
        sys.exit(f"left behind: {leftovers or 'fit_state'}")
    print(f"resume test passed: 4 stops, 6 frames and {len(metrics)} metrics identical "
          f"({again['resumed_frames']} frames resumed by the last run)")


if __name__ == "__main__":
    main()
