#!/usr/bin/python3
"""Writes the fuzzers' seed corpora: small well-formed meshes in every format and encoding the
readers accept, one folder per format (seeds/obj, seeds/off, ...). Usage: make_seeds.py OUT"""
import base64
import os
import struct
import sys
import zlib

# A tetrahedron and a two-triangle square with a quad: enough structure for the fuzzer to mutate.
POINTS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TRIANGLES = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def obj(out):
    v = "".join("v %g %g %g\n" % p for p in POINTS)
    write(out, "tet.obj", v + "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in TRIANGLES))
    write(out, "negative.obj", v + "g body\nf -4 -3 -2\nf 1/1/1 2/2/2 4/4/4\n# comment\n")
    write(out, "quad.obj", v + "f 1 2 3 4\n")


def off(out):
    v = "".join("%g %g %g\n" % p for p in POINTS)
    write(out, "tet.off", "OFF\n4 4 6\n" + v + "".join("3 %d %d %d\n" % t for t in TRIANGLES))
    write(out, "quad.off", "OFF\n# a comment\n4 1 0\n" + v + "4 0 1 2 3\n")


def ply(out):
    header = ("ply\nformat %s 1.0\ncomment seed\nelement vertex 4\nproperty float x\n"
              "property float y\nproperty float z\nelement face 4\n"
              "property list uchar int vertex_indices\nend_header\n")
    write(out, "ascii.ply", header % "ascii" + "".join("%g %g %g\n" % p for p in POINTS)
          + "".join("3 %d %d %d\n" % t for t in TRIANGLES))
    for name, order in (("little.ply", "<"), ("big.ply", ">")):
        body = b"".join(struct.pack(order + "3f", *p) for p in POINTS)
        body += b"".join(struct.pack(order + "B3i", 3, *t) for t in TRIANGLES)
        fmt = "binary_little_endian" if order == "<" else "binary_big_endian"
        write(out, name, (header % fmt).encode() + body)


def stl(out):
    facets = "".join("facet normal 0 0 1\nouter loop\n" + "".join(
        "vertex %g %g %g\n" % POINTS[i] for i in t) + "endloop\nendfacet\n" for t in TRIANGLES)
    write(out, "ascii.stl", "solid seed\n" + facets + "endsolid seed\n")
    body = b"".join(struct.pack("<12fH", 0, 0, 1, *[c for i in t for c in POINTS[i]], 0)
                    for t in TRIANGLES)
    write(out, "binary.stl", b"\0" * 80 + struct.pack("<I", len(TRIANGLES)) + body)


def vtk(out):
    head = "# vtk DataFile Version %s\nseed\n%s\nDATASET POLYDATA\n"
    pts = "POINTS 4 float\n" + " ".join("%g %g %g" % p for p in POINTS) + "\n"
    old = "POLYGONS 4 16\n" + "".join("3 %d %d %d\n" % t for t in TRIANGLES)
    new = ("POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\nCONNECTIVITY vtktypeint64\n"
           + " ".join("%d %d %d" % t for t in TRIANGLES) + "\n")
    write(out, "old.vtk", head % ("3.0", "ASCII") + pts + old + "POINT_DATA 4\nSCALARS s float 1\n"
          "LOOKUP_TABLE default\n1 2 3 4\n")
    write(out, "new.vtk", head % ("5.1", "ASCII") + "FIELD FieldData 1\nTimeValue 1 1 double\n0.5\n"
          + pts + "METADATA\nINFORMATION 0\n\n" + new)
    write(out, "strips.vtk", head % ("4.2", "ASCII") + pts + "TRIANGLE_STRIPS 1 5\n4 0 1 2 3\n")
    bpts = b"POINTS 4 float\n" + b"".join(struct.pack(">3f", *p) for p in POINTS) + b"\n"
    bold = b"POLYGONS 4 16\n" + b"".join(struct.pack(">4i", 3, *t) for t in TRIANGLES) + b"\n"
    bnew = (b"POLYGONS 5 12\nOFFSETS vtktypeint64\n" + struct.pack(">5q", 0, 3, 6, 9, 12)
            + b"\nCONNECTIVITY vtktypeint64\n"
            + b"".join(struct.pack(">3q", *t) for t in TRIANGLES) + b"\n")
    write(out, "binary_old.vtk", (head % ("3.0", "BINARY")).encode() + bpts + bold)
    write(out, "binary_new.vtk", (head % ("5.1", "BINARY")).encode() + bpts + bnew)


def vtp(out):
    conn = [i for t in TRIANGLES for i in t]
    offs = [3 * (k + 1) for k in range(len(TRIANGLES))]
    coords = [c for p in POINTS for c in p]

    def piece(points, connectivity, offsets, fmt):
        return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n<PolyData>\n'
                '<Piece NumberOfPoints="4" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" '
                'NumberOfPolys="4">\n<Points><DataArray type="Float32" NumberOfComponents="3" '
                'format="%s">%s</DataArray></Points>\n<Polys>'
                '<DataArray type="Int64" Name="connectivity" format="%s">%s</DataArray>'
                '<DataArray type="Int64" Name="offsets" format="%s">%s</DataArray></Polys>\n'
                '</Piece>\n</PolyData>\n</VTKFile>\n'
                % (fmt, points, fmt, connectivity, fmt, offsets))

    write(out, "ascii.vtp", piece(" ".join("%g" % c for c in coords),
                                  " ".join(map(str, conn)), " ".join(map(str, offs)), "ascii"))

    def b64(fmt, values):
        raw = struct.pack("<%d%s" % (len(values), fmt), *values)
        return base64.b64encode(struct.pack("<Q", len(raw)) + raw).decode()

    write(out, "binary.vtp", piece(b64("f", coords), b64("q", conn), b64("q", offs), "binary"))

    # As ClothTrack writes its output (the writer's default layout): raw appended data in
    # compressed blocks, each array a header (blocks, block size, last block size, compressed
    # sizes) and its zlib blocks.
    def compressed(fmt, values):
        raw = struct.pack("<%d%s" % (len(values), fmt), *values)
        block = zlib.compress(raw)
        return struct.pack("<4Q", 1, len(raw), len(raw), len(block)) + block

    arrays = [compressed("f", coords), compressed("q", conn), compressed("q", offs)]
    starts = [sum(len(a) for a in arrays[:k]) for k in range(3)]
    header = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" '
              'byte_order="LittleEndian" header_type="UInt64" compressor="vtkZLibDataCompressor">\n'
              '<PolyData>\n<Piece NumberOfPoints="4" NumberOfVerts="0" NumberOfLines="0" '
              'NumberOfStrips="0" NumberOfPolys="4">\n<Points><DataArray type="Float32" '
              'NumberOfComponents="3" format="appended" offset="%d"/></Points>\n<Polys>'
              '<DataArray type="Int64" Name="connectivity" format="appended" offset="%d"/>'
              '<DataArray type="Int64" Name="offsets" format="appended" offset="%d"/></Polys>\n'
              '</Piece>\n</PolyData>\n<AppendedData encoding="raw">\n_' % tuple(starts))
    write(out, "appended_zlib.vtp",
          header.encode() + b"".join(arrays) + b"\n</AppendedData>\n</VTKFile>\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_seeds.py OUT")
    for name, make in (("obj", obj), ("off", off), ("ply", ply), ("stl", stl), ("vtk", vtk),
                       ("vtp", vtp)):
        make(os.path.join(sys.argv[1], name))


if __name__ == "__main__":
    main()
