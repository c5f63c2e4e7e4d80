#!/usr/bin/env python3
"""Each sequence aligned under the built-in body model and under another model file, and whether
the alignment's ground-truth-free figures tell which of the two is the more accurate.

usage: bench/model_choice.py CLOTHTRACK MODEL.vtp OUT NAME=FRAMES[:TRUTH] [NAME=FRAMES[:TRUTH] ...]

Runs `CLOTHTRACK align FRAMES --ground-truth TRUTH -o OUT/NAME-builtin --no-report` and the same
with `--model MODEL.vtp` into OUT/NAME-model (a run whose metrics.json exists is read, not run
again). TRUTH defaults to FRAMES. Prints one Markdown row per sequence: mean error and share
within 10 cm under each model, then the mean per-frame stretch, surface distance, coverage
distance and jitter under each, and whether the model with the lower of each figure is the one
with the lower mean error; last, which alignment `clothtrack align --model builtin --model
MODEL.vtp` keeps (the model's only when it is both less stretched and closer to the frames, each
by more than 2 %: eval/ModelChoice.h) and whether that is the more accurate one.
"""
import json
import os
import subprocess
import sys

FIGURES = [
    ("stretch", lambda m: mean(m["per_frame_stretch"]), "%.4f"),
    ("surface (mm)", lambda m: 1000 * mean(m["per_frame_surface_distance_m"]), "%.2f"),
    ("coverage (cm)", lambda m: 100 * m["mean_coverage_distance_m"], "%.2f"),
    ("jitter (cm)", lambda m: 100 * m["mean_jitter_m"], "%.2f"),
]


MARGIN = 0.02  # kModelChoiceMargin in core/clothtrack/eval/ModelChoice.h


def mean(values):
    values = [v for v in values if v is not None]
    return sum(values) / len(values)


def aligned(clothtrack, frames, truth, out, extra):
    metrics = os.path.join(out, "metrics.json")
    if not os.path.exists(metrics):
        command = [clothtrack, "align", frames, "--ground-truth", truth, "-o", out, "--no-report"]
        with open(out + ".log", "w") as log:
            subprocess.run(command + extra, stdout=log, stderr=subprocess.STDOUT, check=True)
    with open(metrics) as f:
        return json.load(f)


def row(name, builtin, other):
    cells = [name]
    for m in (builtin, other):
        cells.append("%.2f / %.2f %%" % (100 * m["mean_vertex_error_m"], 100 * m["within_10cm"]))
    other_better = other["mean_vertex_error_m"] < builtin["mean_vertex_error_m"]
    for _, figure, form in FIGURES:
        a, b = figure(builtin), figure(other)
        right = (b < a) == other_better
        cells.append("%s / %s %s" % (form % a, form % b, "right" if right else "**wrong**"))
    stretch, surface = FIGURES[0][1], FIGURES[1][1]
    keeps_model = (stretch(other) < stretch(builtin) * (1 - MARGIN) and
                   surface(other) < surface(builtin) * (1 - MARGIN))
    cells.append("%s %s" % ("model" if keeps_model else "built-in",
                            "right" if keeps_model == other_better else "**wrong**"))
    return "| " + " | ".join(cells) + " |"


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__.strip())
    clothtrack, model, out = argv[1], os.path.abspath(argv[2]), argv[3]
    os.makedirs(out, exist_ok=True)
    print("| sequence | built-in: mean / < 10 cm | model | " +
          " | ".join("%s: built-in / model" % label for label, _, _ in FIGURES) + " | kept |")
    print("|---" * (4 + len(FIGURES)) + "|")
    for spec in argv[4:]:
        name, _, paths = spec.partition("=")
        frames, _, truth = paths.partition(":")
        truth = truth or frames
        builtin = aligned(clothtrack, frames, truth, os.path.join(out, name + "-builtin"), [])
        other = aligned(clothtrack, frames, truth, os.path.join(out, name + "-model"),
                        ["--model", model])
        print(row(name, builtin, other), flush=True)


if __name__ == "__main__":
    main(sys.argv)
