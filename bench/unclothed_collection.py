#!/usr/bin/env python3
"""A collection of 20 unrelated poses of one unclothed person, as a scanned collection would be.

usage: bench/unclothed_collection.py MODEL.vtp SYNTH SEED OUT [--random]
       bench/unclothed_collection.py --reposed COLLECTION FRAMES OUT

MODEL is a body model file (`clothtrack import-makehuman ../shared/data/makehuman -o MODEL.vtp`
gives a mesh other than the built-in model's, which then has to fit a body it is not made of).
SYNTH is a folder holding `clothtrack synth` outputs of the presets shirt-armraise,
shirt-crossedarms, trousers-squat, trousers-walkloop, shirt-halfturns, dress-samba and
skirt-turn (each PRESET/body.json). Without --random the poses are frames of those presets; with
--random each joint takes a random rotation within a wide range (legs kicked out, arms crossed
or overhead, bent over). The shape is random, each pose is turned to a random heading and moved
up to 50 cm, and the frames are written as OUT/pose_NN.obj in centimetres with Z up (read them
with `--up z --unit cm`; they are their own ground truth, one vertex order throughout), with
OUT/truth.json (beta, poses) and OUT/poses.txt (where each pose came from).

--reposed writes the built-in model (beta_0 = 0.8, the others 0) in the poses FRAMES
(comma-separated indices) of COLLECTION/truth.json, unturned, in metres with Y up: the same poses
on the mesh the body fit is made of.
"""
import json
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

PRESETS = [("shirt-armraise", 4), ("shirt-crossedarms", 3), ("trousers-squat", 4),
           ("trousers-walkloop", 3), ("shirt-halfturns", 2), ("dress-samba", 2), ("skirt-turn", 2)]


def rotation_matrix(v):
    angle = np.linalg.norm(v)
    if angle < 1e-12:
        return np.eye(3)
    k = np.asarray(v) / angle
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross


def rotation_vector(m):
    angle = np.arccos(np.clip((np.trace(m) - 1) / 2, -1, 1))
    if angle < 1e-12:
        return np.zeros(3)
    axis = np.array([m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]])
    if np.pi - angle < 1e-6:  # half a turn: the axis from the symmetric part
        w, vectors = np.linalg.eigh((m + np.eye(3)) / 2)
        axis = vectors[:, np.argmax(w)]
        return angle * axis / np.linalg.norm(axis)
    return angle * axis / np.linalg.norm(axis)


def random_pose(rng, joints):
    r = np.zeros((len(joints), 3))
    u = rng.uniform
    for side, sign in (("left", 1), ("right", -1)):
        r[joints[side + "_shoulder"]] = [u(-1.0, 0.6), sign * u(-0.8, 0.8), sign * u(-1.3, 1.3)]
        r[joints[side + "_elbow"]] = [u(-2.2, 0), 0, 0]
        hip = u(-1.6, 0.4)
        r[joints[side + "_hip"]] = [hip, sign * u(-0.3, 0.3), sign * u(-0.5, 0.2)]
        r[joints[side + "_knee"]] = [u(0, min(2.0, max(0.3, 0.4 - 1.2 * hip))), 0, 0]
        r[joints[side + "_ankle"]] = [u(-0.4, 0.3), 0, 0]
    r[joints["spine1"]] = [u(-0.2, 0.5), u(-0.4, 0.4), u(-0.2, 0.2)]
    r[joints["spine2"]] = [u(-0.1, 0.3), u(-0.3, 0.3), 0]
    r[joints["neck"]] = [u(-0.3, 0.4), u(-0.5, 0.5), 0]
    return {"rotations": r.tolist(), "translation": [0, 0, 0]}


def write_obj(path, points, triangles, digits="%.4f"):
    with open(path, "w") as f:
        for v in points:
            f.write(("v " + " ".join([digits] * 3) + "\n") % tuple(v))
        for t in triangles:
            f.write("f %d %d %d\n" % tuple(t + 1))


def reposed(collection, frames, out):
    import clothtrack

    truth = json.load(open(os.path.join(collection, "truth.json")))
    os.makedirs(out, exist_ok=True)
    source = clothtrack.ctBodyModelSource()
    source.SetShapeCoefficient(0, 0.8)
    for k, i in enumerate(int(f) for f in frames.split(",")):
        pose = truth["poses"][i]
        for j, r in enumerate(pose["rotations"]):
            source.SetJointRotation(j, *r)
        source.SetTranslation(*pose["translation"])
        source.Modified()
        source.Update()
        mesh = source.GetOutput()
        p = vtk_to_numpy(mesh.GetPoints().GetData())
        triangles = vtk_to_numpy(mesh.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
        write_obj(os.path.join(out, "pose_%02d.obj" % k), p, triangles, "%.5f")


def main(argv):
    if len(argv) == 5 and argv[1] == "--reposed":
        return reposed(argv[2], argv[3], argv[4])
    if len(argv) not in (5, 6) or (len(argv) == 6 and argv[5] != "--random"):
        sys.exit(__doc__.strip())
    import clothtrack

    model, synth, seed, out = argv[1], argv[2], int(argv[3]), argv[4]
    rng = np.random.default_rng(seed)
    os.makedirs(out, exist_ok=True)
    poses = []
    for preset, count in PRESETS:  # drawn in random mode too, so that a seed gives one set
        body = json.load(open(os.path.join(synth, preset, "body.json")))
        for i in rng.choice(len(body["poses"]), count, replace=False):
            poses.append((preset, int(i), body["poses"][i]))
    rng.shuffle(poses)
    joints = {n: i for i, n in enumerate(body["joints"])}
    if len(argv) == 6:
        poses = [("random", k, random_pose(rng, joints)) for k in range(20)]
    source = clothtrack.ctBodyModelSource()
    source.SetModelFileName(model)
    beta = rng.normal(0, 0.7, 4)
    for i, b in enumerate(beta):
        source.SetShapeCoefficient(i, float(b))
    origins, truth = [], []
    for k, (preset, frame, pose) in enumerate(poses):
        rotations = [list(r) for r in pose["rotations"]]
        heading = rotation_matrix([0, rng.uniform(-np.pi, np.pi), 0])
        rotations[0] = list(rotation_vector(heading @ rotation_matrix(rotations[0])))
        for j, r in enumerate(rotations):
            source.SetJointRotation(j, *r)
        translation = [rng.uniform(-0.5, 0.5), pose["translation"][1], rng.uniform(-0.5, 0.5)]
        source.SetTranslation(*translation)
        source.Modified()
        source.Update()
        mesh = source.GetOutput()
        p = vtk_to_numpy(mesh.GetPoints().GetData())
        z_up_cm = np.stack([p[:, 0], -p[:, 2], p[:, 1]], 1) * 100.0
        triangles = vtk_to_numpy(mesh.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
        write_obj(os.path.join(out, "pose_%02d.obj" % k), z_up_cm, triangles)
        origins.append("%02d %s frame %d" % (k, preset, frame))
        truth.append({"rotations": [list(map(float, r)) for r in rotations],
                      "translation": translation})
    json.dump({"beta": list(map(float, beta)), "poses": truth},
              open(os.path.join(out, "truth.json"), "w"))
    open(os.path.join(out, "poses.txt"), "w").write("\n".join(origins) + "\n")


if __name__ == "__main__":
    main(sys.argv)
