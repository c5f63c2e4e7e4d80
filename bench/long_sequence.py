#!/usr/bin/python3
"""Peak memory and time of 'clothtrack align' against the sequence's length.

A long sequence is made by playing a captured one forward and backward (0..N-1, N-2..1, 0..),
named in a list file, so that the motion stays continuous:

    bench/long_sequence.py BUILD/bin/clothtrack ../shared/data/vlasic-samba OUT 175 700 2800

Writes OUT/frames_N.txt, runs align on each into OUT/run_N (--no-report, no ground truth, extra
options after --), and prints per length the peak resident memory (from metrics.json), the
seconds per frame, the frames read again and whether they were kept on disk.
"""
import json
import os
import subprocess
import sys


def played(files, count):
    order = list(range(len(files))) + list(range(len(files) - 2, 0, -1))
    return [files[order[i % len(order)]] for i in range(count)]


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    extra = []
    args = sys.argv[1:]
    if "--" in args:
        extra = args[args.index("--") + 1:]
        args = args[: args.index("--")]
    binary, folder, out, counts = args[0], args[1], args[2], [int(c) for c in args[3:]]
    names = sorted(f for f in os.listdir(folder) if f.endswith((".obj", ".ply", ".off")))
    files = [os.path.abspath(os.path.join(folder, f)) for f in names]
    os.makedirs(out, exist_ok=True)
    print("frames  peak_rss_mb  s/frame  frame_reads  kept_on_disk")
    for count in counts:
        listing = os.path.join(out, "frames_%d.txt" % count)
        with open(listing, "w") as f:
            f.write("\n".join(played(files, count)) + "\n")
        run = os.path.join(out, "run_%d" % count)
        with open(run + ".log", "w") as log:
            subprocess.run([binary, "align", listing, "-o", run, "--no-report"] + extra,
                           stdout=log, stderr=subprocess.STDOUT, check=True)
        m = json.load(open(os.path.join(run, "metrics.json")))
        print("%6d  %11.0f  %7.2f  %11d  %s" % (count, m["peak_rss_mb"], m["seconds_per_frame"],
                                                 m.get("frame_reads", -1),
                                                 m.get("frames_kept_on_disk", "?")), flush=True)


if __name__ == "__main__":
    main()
