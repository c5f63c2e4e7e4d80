#!/usr/bin/env python3
"""How well the frame confidence of `clothtrack align` finds the frames that went wrong.

usage: bench/flag_quality.py [--threshold METRES] OUT [OUT ...]

Each OUT is an align output folder run with --ground-truth. A frame is wrong when its true mean
vertex error is above the threshold (default 0.10 m); it is flagged when metrics.json lists it
in doubtful_frames. Prints, per folder and pooled, the frames, wrong frames, flagged frames,
precision (flagged frames that are wrong) and recall (wrong frames that are flagged). The
template frame is left out (its error is the capture's own).
"""
import argparse
import json
import os
import sys


def counts(folder, threshold):
    with open(os.path.join(folder, "metrics.json")) as f:
        metrics = json.load(f)
    if "per_frame_mean_error_m" not in metrics or "doubtful_frames" not in metrics:
        sys.exit("%s: metrics.json lacks per_frame_mean_error_m or doubtful_frames (run align with "
                 "--ground-truth)" % folder)
    errors = metrics["per_frame_mean_error_m"]
    flagged = {d["frame"] for d in metrics["doubtful_frames"]}
    template = metrics["template_frame"]
    frames = [k for k in range(len(errors)) if k != template and errors[k] is not None]
    wrong = {k for k in frames if errors[k] > threshold}
    return len(frames), wrong, flagged & set(frames)


def line(name, frames, wrong, flagged):
    hits = len(wrong & flagged)
    precision = "%.2f" % (hits / len(flagged)) if flagged else "-"
    recall = "%.2f" % (hits / len(wrong)) if wrong else "-"
    print("| %s | %d | %d | %d | %s | %s |" % (name, frames, len(wrong), len(flagged), precision, recall))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--threshold", type=float, default=0.10)
    args = parser.parse_args()
    print("| run | frames | wrong (> %.0f cm) | flagged | precision | recall |" % (100 * args.threshold))
    print("|---|---|---|---|---|---|")
    total_frames, total_wrong, total_flagged, offset = 0, set(), set(), 0
    for folder in args.folders:
        frames, wrong, flagged = counts(folder, args.threshold)
        line(os.path.basename(os.path.normpath(folder)), frames, wrong, flagged)
        total_frames += frames
        total_wrong |= {offset + k for k in wrong}
        total_flagged |= {offset + k for k in flagged}
        offset += 100000
    if len(args.folders) > 1:
        line("all", total_frames, total_wrong, total_flagged)


if __name__ == "__main__":
    main()
