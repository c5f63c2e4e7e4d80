#!/usr/bin/env python3
"""Align a captured sequence with one call and look at the result with numpy.

    python3 align_sequence.py FRAMES [--ground-truth GT] [--template K] [--solver exact|lbfgs] [-o OUT.npz]

FRAMES: a folder of frames (e.g. the frames/ folder of `clothtrack synth`, or ../shared/data/vlasic-samba).
Prints the template frame and the metrics; with -o, saves the aligned vertex positions (frames x
vertices x 3), the template's triangles and the per-vertex errors as a numpy .npz file.
"""
import argparse
import sys

import numpy as np

import clothtrack


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("frames")
    parser.add_argument("--ground-truth")
    parser.add_argument("--template", type=int)
    parser.add_argument("--solver", default="exact", choices=["exact", "lbfgs"])
    parser.add_argument("-o", "--output", help="write positions, faces and errors to this .npz file")
    args = parser.parse_args()

    def progress(stage, fraction):
        print("\r%-16s %3d%%" % (stage, 100 * fraction), end="" if fraction < 1 else "\n", file=sys.stderr)

    try:
        result = clothtrack.align(args.frames, ground_truth=args.ground_truth, template_frame=args.template,
                                  solver=args.solver, progress=progress)
    except (RuntimeError, ValueError) as error:
        sys.exit("align_sequence: %s" % error)

    print("template frame %d, %d frames, %d vertices" % (result.template_frame, *result.positions.shape[:2]))
    for key, value in result.metrics.items():
        if not isinstance(value, list):
            print("  %-24s %s" % (key, value))
    # The aligned template's vertex paths: e.g. how far each vertex travels over the sequence.
    travel = np.linalg.norm(np.diff(result.positions, axis=0), axis=2).sum(axis=0)
    print("  vertex travel (m)        median %.3f, max %.3f" % (np.median(travel), travel.max()))
    if args.output:
        arrays = {"positions": result.positions, "faces": result.faces}
        if result.errors is not None:
            arrays["errors"] = result.errors
        np.savez_compressed(args.output, **arrays)
        print("wrote", args.output)


if __name__ == "__main__":
    main()
