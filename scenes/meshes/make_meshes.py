#!/usr/bin/env python3
"""Writes the OBJ meshes of the lecture scenes (our own geometry, no downloaded models).

    python3 scenes/meshes/make_meshes.py    # rewrites table.obj, round_cloth.obj, poncho.obj, two_layers.obj, mannequin.obj

Every solid is closed, its triangles counter-clockwise seen from outside (normals point out).
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, comment, verts, tris):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# %s\n# written by make_meshes.py: %d vertices, %d triangles\n" % (comment, len(verts), len(tris)))
        for v in verts:
            f.write("v %.6f %.6f %.6f\n" % v)
        for t in tris:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def box(verts, tris, c, e):
    """An axis-aligned box, centre c, half extents e: 8 corners, 12 outward triangles."""
    base = len(verts)
    for i in range(8):
        verts.append(tuple(c[k] + (e[k] if (i >> k) & 1 else -e[k]) for k in range(3)))
    # faces as corner bit patterns, counter-clockwise from outside
    for q in [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]:
        tris.append((base + q[0], base + q[1], base + q[2]))
        tris.append((base + q[0], base + q[2], base + q[3]))


def lathe(profile, segments=40):
    """One closed surface of revolution with elliptic sections: profile rows (y, r_x, r_z) from the bottom
    pole (radii 0) to the top pole (radii 0); outward triangles."""
    verts, tris = [(0.0, profile[0][0], 0.0)], []
    for y, rx, rz in profile[1:-1]:
        for i in range(segments):
            a = 2 * math.pi * i / segments
            verts.append((rx * math.cos(a), y, -rz * math.sin(a)))
    verts.append((0.0, profile[-1][0], 0.0))
    ring = lambda k, i: 1 + k * segments + i % segments
    rings, top = len(profile) - 2, len(verts) - 1
    for i in range(segments):
        tris.append((0, ring(0, i + 1), ring(0, i)))
        tris.append((top, ring(rings - 1, i), ring(rings - 1, i + 1)))
    for k in range(rings - 1):
        for i in range(segments):
            tris.append((ring(k, i), ring(k, i + 1), ring(k + 1, i + 1)))
            tris.append((ring(k, i), ring(k + 1, i + 1), ring(k + 1, i)))
    return verts, tris


# A tailor's dummy as (height, half width, half depth), m: hips, waist, chest, shoulders, neck, head.
DUMMY = [(0.80, 0, 0), (0.82, 0.14, 0.10), (0.95, 0.19, 0.13), (1.10, 0.16, 0.11), (1.30, 0.19, 0.13),
         (1.45, 0.22, 0.12), (1.52, 0.24, 0.11), (1.56, 0.20, 0.09), (1.59, 0.07, 0.065), (1.64, 0.055, 0.055),
         (1.68, 0.08, 0.085), (1.74, 0.095, 0.10), (1.80, 0.085, 0.09), (1.85, 0.05, 0.055), (1.87, 0, 0)]


def disc(radius, rings, hole_rings=0):
    """A flat disc in the x-z plane (normal +y): ring k has 6k vertices at radius k R / rings;
    the innermost `hole_rings` rings are left out (an annulus: a poncho's neck hole)."""
    verts, index = [], {}
    for k in range(hole_rings, rings + 1):
        n = max(1, 6 * k)
        for i in range(n):
            a = 2 * math.pi * i / n
            index[(k, i)] = len(verts)
            verts.append((radius * k / rings * math.cos(a), 0.0, -radius * k / rings * math.sin(a)))
    tris = []
    for k in range(max(1, hole_rings + 1), rings + 1):
        inner, outer = max(1, 6 * (k - 1)), 6 * k
        steps = inner if k > 1 else 0  # the centre (k = 1) is one vertex: a fan
        i = j = 0  # walk both rings by angle, always advancing the one whose next vertex comes first
        while i < steps or j < outer:
            a_i = (i + 1) / inner if k > 1 else 2.0
            a_j = (j + 1) / outer
            if j < outer and (a_j <= a_i or i >= steps):
                tris.append((index[(k - 1, i % inner)], index[(k, j % outer)], index[(k, (j + 1) % outer)]))
                j += 1
            else:
                tris.append((index[(k - 1, i % inner)], index[(k, j % outer)], index[(k - 1, (i + 1) % inner)]))
                i += 1
    return verts, tris


def grid(verts, tris, n, a, x0, y, z0):
    """An n x n grid of spacing a in the plane y, starting at (x0, y, z0); two triangles per square."""
    base = len(verts)
    for j in range(n):
        for i in range(n):
            verts.append((x0 + i * a, y, z0 + j * a))
    at = lambda i, j: base + j * n + i
    for j in range(n - 1):
        for i in range(n - 1):
            tris.append((at(i, j), at(i, j + 1), at(i + 1, j + 1)))
            tris.append((at(i, j), at(i + 1, j + 1), at(i + 1, j)))


def main():
    v, t = [], []
    box(v, t, (0.0, 0.735, 0.0), (0.6, 0.025, 0.4))  # table top, 1.2 m x 0.8 m, top face at 0.76 m
    for sx in (-1, 1):
        for sz in (-1, 1):
            box(v, t, (sx * 0.54, 0.355, sz * 0.34), (0.03, 0.355, 0.03))
    write("table.obj", "a table: a 1.2 m x 0.8 m top at 0.76 m on four legs", v, t)

    v, t = disc(0.9, 14)
    write("round_cloth.obj", "a round tablecloth, radius 0.9 m, in the x-z plane", v, t)

    v, t = disc(0.77, 14, hole_rings=2)
    write("poncho.obj", "a poncho: a disc of radius 0.77 m with a neck hole of radius 0.11 m, in the x-z plane", v, t)

    v, t = [], []  # the upper layer first (particle 0 is in it), each of its particles above the centre of a square below
    grid(v, t, 7, 0.03, 0.015, 0.05, 0.015)
    grid(v, t, 8, 0.03, 0.0, 0.0, 0.0)
    write("two_layers.obj", "two layers of spacing 0.03 m: 7 x 7 particles at y = 0.05 m above the centres of the squares of 8 x 8 at y = 0", v, t)

    v, t = lathe(DUMMY)
    write("mannequin.obj", "a tailor's dummy from 0.8 m to 1.87 m: one closed surface of revolution (elliptic sections)", v, t)


if __name__ == "__main__":
    main()
