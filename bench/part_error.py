#!/usr/bin/env python3
"""Where on the body an alignment's error lies: the mean vertex error per body part.

usage: PYTHONPATH=build/lib/python3/dist-packages bench/part_error.py [--step K] [--frames A-B]
       OUT [OUT ...]

Each OUT is a `clothtrack align` output folder run with --ground-truth (its aligned/*.vtp carry the
Error point array) and its body_fit.json. Each template vertex belongs to the body part of the
nearest vertex of the body fitted to the template frame (the joint that moves it most, grouped:
torso, head, upper arms, forearms and hands, thighs, shins, feet). Prints, per folder, the share of
the template's vertices in each part and their mean error (cm) over every K-th frame (default 3)
of the range A-B (default all), the template frame left out.
"""
import argparse
import json
import os
import sys

import numpy as np
import vtk
from scipy.spatial import cKDTree
from vtk.util.numpy_support import vtk_to_numpy

# The built-in model's joints, in its order (core/clothtrack/body/Skeleton.h).
JOINTS = ("pelvis", "spine1", "spine2", "spine3", "neck", "head", "left_clavicle",
          "left_shoulder", "left_elbow", "left_wrist", "right_clavicle", "right_shoulder",
          "right_elbow", "right_wrist", "left_hip", "left_knee", "left_ankle", "left_toe",
          "right_hip", "right_knee", "right_ankle", "right_toe")
PARTS = {
    "torso": ("pelvis", "spine1", "spine2", "spine3", "left_clavicle", "right_clavicle"),
    "head": ("neck", "head"),
    "upper arms": ("left_shoulder", "right_shoulder"),
    "forearms and hands": ("left_elbow", "left_wrist", "right_elbow", "right_wrist"),
    "thighs": ("left_hip", "right_hip"),
    "shins": ("left_knee", "right_knee"),
    "feet": ("left_ankle", "left_toe", "right_ankle", "right_toe"),
}


def read_aligned(out, frame):
    path = os.path.join(out, "aligned", "aligned_%04d.vtp" % frame)
    if not os.path.exists(path):
        sys.exit(f"{path}: missing (run align without --no-write, with --ground-truth)")
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def template_body(out, frame):
    """Vertices and dominant joints of the body fitted to the template frame."""
    import clothtrack  # the build's Python package (see usage)

    with open(os.path.join(out, "body_fit.json")) as f:
        fit = json.load(f)
    source = clothtrack.ctBodyModelSource()
    for i, b in enumerate(fit["beta"]):
        source.SetShapeCoefficient(i, b)
    pose = fit["per_frame"][frame]
    for j, r in enumerate(pose["rotations"]):
        source.SetJointRotation(j, *r)
    source.SetTranslation(*pose["translation"])
    source.Update()
    body = source.GetOutput()
    weights = body.GetPointData().GetArray("SkinWeights")
    if weights is None or weights.GetNumberOfComponents() != len(JOINTS):
        sys.exit(f"{out}: the body has no SkinWeights of the built-in model's {len(JOINTS)} joints")
    points = vtk_to_numpy(body.GetPoints().GetData())
    return points, vtk_to_numpy(weights).argmax(axis=1)


def part_errors(out, step, first, last):
    with open(os.path.join(out, "metrics.json")) as f:
        metrics = json.load(f)
    if metrics.get("up", "y") != "y":
        sys.exit(f"{out}: up axis {metrics['up']}: only Y-up runs are supported")
    template = metrics["template_frame"]
    scale = metrics.get("unit_scale", 1.0) or 1.0
    names = JOINTS
    body, joint = template_body(out, template)
    positions = vtk_to_numpy(read_aligned(out, template).GetPoints().GetData()) * scale
    _, nearest = cKDTree(body).query(positions)
    vertex_joint = joint[nearest]
    masks = {p: np.isin(vertex_joint, [names.index(j) for j in js]) for p, js in PARTS.items()}
    count = len(metrics["per_frame_mean_error_m"])
    last = count - 1 if last is None else min(last, count - 1)
    sums = {p: [] for p in PARTS}
    for k in range(first, last + 1, step):
        if k == template:
            continue
        error = read_aligned(out, k).GetPointData().GetArray("Error")
        if error is None:
            sys.exit(f"{out}: frame {k} has no Error array (run align with --ground-truth)")
        error = vtk_to_numpy(error) * scale
        for p, mask in masks.items():
            known = error[mask][np.isfinite(error[mask])]  # NaN: no ground truth near the vertex
            if known.size:
                sums[p].append(known.mean())
    share = {p: mask.mean() for p, mask in masks.items()}
    return share, {p: (100 * np.mean(v) if v else float("nan")) for p, v in sums.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outs", nargs="+", metavar="OUT")
    parser.add_argument("--step", type=int, default=3)
    parser.add_argument("--frames", default=None, help="A-B: the frames to average over")
    args = parser.parse_args()
    first, last = 0, None
    if args.frames:
        a, b = args.frames.split("-")
        first, last = int(a), int(b)
    header = " | ".join(PARTS)
    print(f"| run | {header} |")
    print("|---|" + "---|" * len(PARTS))
    for out in args.outs:
        share, error = part_errors(out, max(1, args.step), first, last)
        cells = " | ".join(f"{error[p]:.1f} ({100 * share[p]:.0f} %)" for p in PARTS)
        print(f"| {os.path.basename(os.path.normpath(out))} | {cells} |")


if __name__ == "__main__":
    main()
