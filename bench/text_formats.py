#!/usr/bin/env python3
"""Writes OFF and ASCII PLY copies of OBJ frames, the same vertices and faces as text, and a
binary STL copy (triangles only), for bench_read. usage: bench/text_formats.py OUT OBJ..."""
import os
import struct
import sys


def write_binary_stl(path, points, faces):
    xyz = [tuple(map(float, p.split())) for p in points]
    triangles = [f for f in faces if len(f) == 3]
    with open(path, "wb") as f:
        f.write(b"binary STL".ljust(80, b" ") + struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))
            for v in t:
                f.write(struct.pack("<3f", *xyz[v]))
            f.write(b"\0\0")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for path in sys.argv[2:]:
        points, faces = [], []
        with open(path) as f:
            for line in f:
                if line.startswith("v "):
                    points.append(" ".join(line.split()[1:4]))
                elif line.startswith("f "):
                    faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
        stem = os.path.join(out, os.path.splitext(os.path.basename(path))[0])
        body = "".join(p + "\n" for p in points) + "".join(
            "%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)
        with open(stem + ".off", "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(points), len(faces)) + body)
        with open(stem + ".ply", "w") as f:
            f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                    "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
                    "end_header\n" % (len(points), len(faces)) + body)
        write_binary_stl(stem + ".stl", points, faces)


if __name__ == "__main__":
    main()
