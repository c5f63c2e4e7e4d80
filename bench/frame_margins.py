#!/usr/bin/env python3
"""How far each sequence's frames are from the frame-consistency warnings of `clothtrack align`
(core/clothtrack/mesh/FrameConsistency.h): each frame's size (square root of its surface area)
over the sequence's median, the largest step of the bounding-box centre between consecutive frames
in median subject heights, and, with a ground_truth folder beside frames, the ground truth's size
over the input's.

usage: bench/frame_margins.py FOLDER [FOLDER ...]
Each FOLDER holds OBJ frames, or frames/ and ground_truth/ folders of OBJ frames (as `clothtrack
synth` writes them). Every tenth frame is compared with its ground truth.
"""
import glob
import os
import sys

import numpy as np


def extent(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                points.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                ids = [int(t.split("/")[0]) for t in line.split()[1:]]
                faces += [[ids[0], ids[i], ids[i + 1]] for i in range(1, len(ids) - 1)]
    v = np.array(points)
    t = np.array(faces) - 1
    t[t < 0] += len(v) + 1  # negative (relative) indices
    area = 0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]),
                                axis=1).sum()
    low, high = v.min(0), v.max(0)
    return np.sqrt(area), (low + high) / 2, high[1] - low[1]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in sys.argv[1:]:
        frames_dir = os.path.join(folder, "frames")
        frames = sorted(glob.glob(os.path.join(frames_dir if os.path.isdir(frames_dir) else folder,
                                               "*.obj")))
        if not frames:
            print(f"{folder}: no OBJ frame")
            continue
        e = [extent(f) for f in frames]
        size = np.array([x[0] for x in e])
        centre = np.array([x[1] for x in e])
        height = np.median([x[2] for x in e])
        ratio = size / np.median(size)
        steps = np.linalg.norm(np.diff(centre, axis=0), axis=1) / height if len(e) > 1 else [0]
        line = (f"{folder}: {len(frames)} frames, size ratio {ratio.min():.2f}-{ratio.max():.2f}, "
                f"largest step {max(steps):.3f} heights")
        truth = sorted(glob.glob(os.path.join(folder, "ground_truth", "*.obj")))
        if len(truth) == len(frames):
            pairs = [(extent(a), extent(b)) for a, b in list(zip(frames, truth))[::10]]
            gt = [b[0] / a[0] for a, b in pairs]
            line += f", ground truth / input size {min(gt):.2f}-{max(gt):.2f}"
        print(line)


if __name__ == "__main__":
    main()
