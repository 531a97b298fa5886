#!/usr/bin/python3
"""Midpoint subdivision of a closed triangle mesh (each triangle into four, shared edge midpoints
welded), repeated LEVELS times, written as binary PLY: a mesh with 4^LEVELS times the triangles
and the same solid, for benchmarks that need more triangles than the bundled meshes have.

    /usr/bin/python3 bench/subdivide.py IN.obj|IN.off LEVELS OUT.ply
"""
import sys

import numpy as np


def read_mesh(path):
    vertices, faces = [], []
    with open(path) as f:
        if path.endswith(".off"):
            words = f.read().split()
            nv, nf = int(words[1]), int(words[2])
            at = 4
            vertices = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
            at += 3 * nv
            for _ in range(nf):
                k = int(words[at])
                faces.append([int(w) for w in words[at + 1:at + 1 + k]])
                at += 1 + k
            return vertices, np.array(faces, dtype=np.int64)
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == "v":
                vertices.append([float(x) for x in p[1:4]])
            elif p[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in p[1:4]])
    return np.array(vertices), np.array(faces, dtype=np.int64)


def subdivide(v, f):
    edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    key = np.sort(edges, axis=1)
    unique, inverse = np.unique(key, axis=0, return_inverse=True)
    mid = len(v) + inverse.reshape(3, -1).T  # the midpoint of edges 01, 12, 20 of each face
    v2 = np.concatenate([v, 0.5 * (v[unique[:, 0]] + v[unique[:, 1]])])
    a, b, c = f[:, 0], f[:, 1], f[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    f2 = np.concatenate([np.stack([a, ab, ca], 1), np.stack([ab, b, bc], 1),
                         np.stack([ca, bc, c], 1), np.stack([ab, bc, ca], 1)])
    return v2, f2


def main():
    source, levels, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    v, f = read_mesh(source)
    for _ in range(levels):
        v, f = subdivide(v, f)
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
              "property float x\nproperty float y\nproperty float z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (len(v), len(f)))
    faces = np.zeros(len(f), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"] = 3
    faces["i"] = f
    with open(out, "wb") as g:
        g.write(header.encode())
        g.write(v.astype("<f4").tobytes())
        g.write(faces.tobytes())
    print("%s: %d vertices, %d triangles" % (out, len(v), len(f)), file=sys.stderr)


if __name__ == "__main__":
    main()
