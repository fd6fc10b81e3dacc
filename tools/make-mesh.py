#!/usr/bin/env python3
"""Writes a big triangle mesh as binary little-endian PLY for the mesh benchmark (tools/bench-mesh.sh).

The surface is a terrain: an N x N vertex grid over [-1, 1]^2 in x and z, its height y a sum of sines, so
every triangle is distinct and the BVH has real work. N x N vertices give 2 (N-1)^2 triangles; the default
N = 2238 gives 10,008,338 triangles (about 190 MB). Pure Python (no numpy in Debian's base set).

usage: tools/make-mesh.py OUT.ply [--triangles COUNT]
"""
import argparse
import math
import struct


def grid_size(triangles):
    """Smallest N with 2 (N-1)^2 >= triangles."""
    return math.ceil(math.sqrt(triangles / 2)) + 1


def height(x, z):
    return 0.08 * math.sin(9 * x) * math.cos(7 * z) + 0.02 * math.sin(41 * x + 13 * z) + 0.01 * math.cos(97 * z)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--triangles", type=int, default=10_000_000)
    args = parser.parse_args()
    n = grid_size(args.triangles)
    faces = 2 * (n - 1) ** 2
    with open(args.out, "wb") as f:
        f.write(
            (
                "ply\nformat binary_little_endian 1.0\ncomment snell tools/make-mesh.py terrain\n"
                f"element vertex {n * n}\nproperty float x\nproperty float y\nproperty float z\n"
                f"element face {faces}\nproperty list uchar int vertex_indices\nend_header\n"
            ).encode()
        )
        step = 2.0 / (n - 1)
        for j in range(n):
            z = -1 + j * step
            row = []
            for i in range(n):
                x = -1 + i * step
                row.append((x, height(x, z), z))
            f.write(b"".join(struct.pack("<fff", *p) for p in row))
        tri = struct.Struct("<Biii")
        for j in range(n - 1):
            out = []
            for i in range(n - 1):
                a = j * n + i
                b, c, d = a + 1, a + n, a + n + 1
                out.append(tri.pack(3, a, c, b))
                out.append(tri.pack(3, b, c, d))
            f.write(b"".join(out))
    print(f"{args.out}: {n * n} vertices, {faces} triangles")


if __name__ == "__main__":
    main()
