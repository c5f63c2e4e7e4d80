#!/usr/bin/env python3
"""A collection of unrelated poses made from a sequence: every STEP-th frame, in a shuffled order.

usage: bench/shuffled_collection.py FRAMES STEP COUNT SEED OUT.txt [TRUTH OUT_TRUTH.txt]

FRAMES is a folder of numbered mesh files (sorted by name). Writes the list file OUT.txt of COUNT
frames (0, STEP, 2 STEP, ...) shuffled by Python's random.shuffle with SEED, and, given TRUTH, the
list of the same ground-truth frames in the same order. `clothtrack align OUT.txt --ground-truth
OUT_TRUTH.txt` then aligns a set of poses whose consecutive frames are unrelated.
"""
import os
import random
import sys


def frames(folder):
    names = sorted(n for n in os.listdir(folder) if not n.startswith("."))
    if not names:
        sys.exit("%s: no frame" % folder)
    return [os.path.abspath(os.path.join(folder, n)) for n in names]


def main(argv):
    if len(argv) not in (6, 8):
        sys.exit(__doc__.strip())
    folder, step, count, seed, out = argv[1], int(argv[2]), int(argv[3]), int(argv[4]), argv[5]
    files = frames(folder)
    chosen = list(range(0, len(files), step))[:count]
    random.seed(seed)
    random.shuffle(chosen)
    outputs = [(files, out)]
    if len(argv) == 8:
        truth = frames(argv[6])
        if len(truth) != len(files):
            sys.exit("%s: %d frames, %s has %d" % (argv[6], len(truth), folder, len(files)))
        outputs.append((truth, argv[7]))
    for source, path in outputs:
        with open(path, "w") as f:
            f.writelines(source[k] + "\n" for k in chosen)
    print("frames:", " ".join(str(k) for k in chosen))


if __name__ == "__main__":
    main(sys.argv)
