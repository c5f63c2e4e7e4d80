#!/usr/bin/env python3
"""Summarise a run on point clouds against the same run on meshes, as BENCHMARKS.md tables.

usage: /usr/bin/python3 bench/point_clouds.py MESH_OUT CLOUD_OUT

MESH_OUT and CLOUD_OUT are output folders of `clothtrack align ... --ground-truth GT`, the second
given the clouds (its reconstruction is in CLOUD_OUT/reconstructed/reconstruction.json).
"""
import collections
import json
import os
import statistics
import sys


def load(path):
    with open(path) as f:
        return json.load(f)


def accuracy_row(name, metrics):
    per_frame = metrics["per_frame_mean_error_m"]
    worst = max(range(len(per_frame)), key=lambda k: per_frame[k])
    return "| %s | %.2f cm | %.2f cm | %.2f %% | %d: %.1f cm | %d | %.2f | %.0f MB |" % (
        name, 100 * metrics["mean_vertex_error_m"], 100 * metrics["p90_vertex_error_m"],
        100 * metrics["within_10cm"], worst, 100 * per_frame[worst], metrics["template_frame"],
        metrics["seconds_per_frame"], metrics["peak_rss_mb"])


def spread(values, scale=1.0, digits=2):
    fmt = "%%.%df" % digits
    return (fmt + " / " + fmt + " / " + fmt) % (scale * min(values), scale * statistics.mean(values),
                                                scale * max(values))


def main():
    mesh_out, cloud_out = sys.argv[1:3]
    mesh, cloud = load(os.path.join(mesh_out, "metrics.json")), load(os.path.join(cloud_out, "metrics.json"))
    frames = load(os.path.join(cloud_out, "reconstructed", "reconstruction.json"))["frames"]
    print("| input | mean | p90 | < 10 cm | worst frame | template | s/frame (align) | peak |")
    print("|---|---|---|---|---|---|---|---|")
    print(accuracy_row("meshes", mesh))
    print(accuracy_row("depth clouds, reconstructed", cloud))
    print()
    print("Reconstruction, per frame (min / mean / max over %d frames):" % len(frames))
    print()
    print("| quantity | min / mean / max |")
    print("|---|---|")
    rows = [("points", "points", 1, 0), ("stray points removed", "outliers", 1, 0),
            ("points after thinning", "thinned_points", 1, 0), ("vertices", "vertices", 1, 0),
            ("faces", "faces", 1, 0), ("pieces", "pieces", 1, 0), ("boundary loops", "boundary_loops", 1, 0),
            ("genus of the largest piece", "genus", 1, 2), ("Poisson unpaired edges", "poisson_unpaired_edges", 1, 2),
            ("mean point distance (mm)", "mean_point_distance_m", 1000, 2),
            ("points > 1 cm from the surface (%)", "unexplained_share", 100, 3),
            ("seconds", "seconds", 1, 2)]
    for label, key, scale, digits in rows:
        print("| %s | %s |" % (label, spread([f[key] for f in frames], scale, digits)))
    for step in ("cleaning", "normals", "poisson", "crop"):
        print("| seconds: %s | %s |" % (step, spread([f["seconds_per_step"][step] for f in frames])))
    genus = collections.Counter(f["genus"] for f in frames)
    pieces = collections.Counter(f["pieces"] for f in frames)
    doubtful = sum(1 for f in frames if f["doubts"])
    print()
    print("genus: %s; pieces: %s; doubtful reconstructions: %d" % (
        ", ".join("%d frames %d" % (n, g) for g, n in sorted(genus.items())),
        ", ".join("%d frames %d" % (n, p) for p, n in sorted(pieces.items())), doubtful))


if __name__ == "__main__":
    main()
