#!/usr/bin/env python3
"""How far the body fitted by `clothtrack body-fit` (or `align`) is from the simulator's true pose.

usage: bench/pose_error.py DATA/P/body.json OUT [OUT ...]

DATA/P/body.json is written by `clothtrack synth` beside the frames it simulates; each OUT is a
`body-fit` or `align` output folder with a body_fit.json of the same frames. Prints, per folder:
the mean absolute error of the hips' and knees' flexion (their rotation about X, radians), its
worst frame, and the mean error of the rotation vectors of every joint but the root (radians).
The joints' rotations are compared as parameters; both use the built-in model's axes.
"""
import json
import math
import sys

LEG_JOINTS = ("left_hip", "left_knee", "right_hip", "right_knee")


def load(path):
    with open(path) as f:
        return json.load(f)


def errors(truth, fitted):
    names = truth["joints"]
    legs = [names.index(n) for n in LEG_JOINTS]
    frames = fitted["per_frame"]
    if len(frames) != len(truth["poses"]):
        raise ValueError(f"{len(frames)} fitted frames against {len(truth['poses'])} true poses")
    leg_sum, worst, all_sum = 0.0, (0.0, -1), 0.0
    for k, fit in enumerate(frames):
        true_rotations = truth["poses"][k]["rotations"]
        rotations = fit["rotations"]
        frame_legs = sum(abs(true_rotations[j][0] - rotations[j][0]) for j in legs) / len(legs)
        leg_sum += frame_legs
        worst = max(worst, (frame_legs, k))
        all_sum += sum(math.dist(true_rotations[j], rotations[j])
                       for j in range(1, len(names))) / (len(names) - 1)
    n = len(frames)
    return leg_sum / n, worst, all_sum / n


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__.strip().splitlines()[2])
    truth = load(sys.argv[1])
    print("| run | hip and knee flexion error (rad) | worst frame | all joints (rad) |")
    print("|---|---|---|---|")
    for folder in sys.argv[2:]:
        try:
            legs, (worst, frame), joints = errors(truth, load(folder + "/body_fit.json"))
        except (OSError, ValueError, KeyError) as e:
            sys.exit(f"pose_error: {folder}: {e}")
        print(f"| {folder} | {legs:.3f} | {frame}: {worst:.3f} | {joints:.3f} |")


if __name__ == "__main__":
    main()
