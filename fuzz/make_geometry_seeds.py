#!/usr/bin/env python3
"""Writes the seed corpora of the geometric fuzz targets (fuzz_ccd_vs_exact, fuzz_plane_vs_exact,
fuzz_selfcollide_continuous) into data/fuzz/<target>/: one small file per degenerate family, in
the byte layouts documented at the top of each target (coordinates as fuzz/fuzz_coordinates.h
reads them). Run from the repository root: python3 fuzz/make_geometry_seeds.py
Deterministic; rewriting the files with unchanged families gives the same bytes."""
import os
import struct
from fractions import Fraction


def coord(x):
    """The shortest encoding of x: small integer (mode 1), dyadic n/2^k (mode 2), else raw (mode 0)."""
    if isinstance(x, bytes):  # a pre-encoded coordinate (copies, ulp nudges, extreme exponents)
        return x
    f = Fraction(x)
    if f.denominator == 1 and -4 <= f <= 4:
        return bytes([1, int(f) + 4])
    for k in range(11):
        n = f * (1 << k)
        if n.denominator == 1 and -128 <= n <= 127:
            return bytes([2, int(n) & 0xFF, k])
    return bytes([0]) + struct.pack("<d", float(x))


def nudge(index, steps):
    """Mode 4: coordinate `index` moved by `steps` ulps (-4..3)."""
    return bytes([4, index, (steps * 32) & 0xFF])


def extreme(n, e):
    """Mode 5: n * 2^e."""
    return bytes([5, n & 0xFF]) + struct.pack("<H", e + 1100)


def coords(points):
    return b"".join(coord(c) for p in points for c in p)


def write(target, name, data):
    folder = os.path.join("data", "fuzz", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def ccd_seeds():
    t = "fuzz_ccd_vs_exact"
    # vertex-face: the vertex falls through a static face at t = 1/2.
    face = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    vf0 = [(0.25, 0.25, 1)] + face
    vf1 = [(0.25, 0.25, -1)] + face
    # edge-edge: edge b falls across static edge a at t = 1/2.
    ee0 = [(0, 0, 0), (1, 0, 0), (0.5, -1, 1), (0.5, 1, 1)]
    ee1 = [(0, 0, 0), (1, 0, 0), (0.5, -1, -1), (0.5, 1, -1)]
    params = bytes([0x55, 0xA3, 0x05, 100])
    families = [
        ("through", 0, 0), ("coplanar_static", 2, 0), ("coplanar_moving", 4, 0), ("degenerate", 8, 0),
        ("parallel_or_translated", 16, 0), ("contact_t0", 32, 0), ("contact_t1", 64, 0), ("static_points", 128, 0),
        ("scaled", 0, 1), ("point_or_double_degenerate", 0, 2), ("coincide_t0", 0, 4), ("coincide_t1", 0, 12),
        ("time_reversed", 0, 16), ("coplanar_degenerate_t0", 2 | 8 | 32, 0), ("parallel_coplanar", 16 | 2, 0),
        ("coplanar_contact_t1", 4 | 64, 0),
    ]
    for kind, x0, x1 in (("vf", vf0, vf1), ("ee", ee0, ee1)):
        for name, a, b in families:
            write(t, f"{kind}_{name}", bytes([a | (kind == "ee"), b]) + coords(x0) + coords(x1) + params)
    # Grazing contacts: the vertex through the face's corner, and nudged one ulp off it.
    corner0, corner1 = [(1, 0, 1)] + face, [(1, 0, -1)] + face
    write(t, "vf_through_corner", bytes([0, 0]) + coords(corner0) + coords(corner1))
    nudged = [coord(c) for p in corner0 + corner1 for c in p]
    nudged[12] = nudge(0, 1)  # x1[0].x one ulp past the corner
    write(t, "vf_corner_ulp_off", bytes([0, 0]) + b"".join(nudged))
    # Edges meeting exactly end to end at t = 1, and their tiny and huge copies.
    e0 = [(0, 0, 0), (1, 0, 0), (2, 1, 1), (2, 2, 1)]
    e1 = [(0, 0, 0), (1, 0, 0), (1, 0, 0), (1, 1, 0)]
    write(t, "ee_end_to_end_t1", bytes([1, 0]) + coords(e0) + coords(e1))
    tiny = [extreme(c * 4 if c else 0, -1070) if c else coord(0) for p in e0 + e1 for c in p]
    write(t, "ee_subnormal", bytes([1, 0]) + b"".join(tiny))
    huge = [extreme(c * 4 if c else 0, 1000) if c else coord(0) for p in e0 + e1 for c in p]
    write(t, "ee_huge", bytes([1, 0]) + b"".join(huge))
    # Raw doubles with a tiny offset: a near miss just below the face.
    raw0 = [(0.25, 0.25, 1)] + face
    raw1 = [(0.25, 0.25, 2.0 ** -60)] + face
    write(t, "vf_near_miss", bytes([0, 0]) + b"".join(bytes([0]) + struct.pack("<d", c) for p in raw0 + raw1 for c in p))


def plane_seeds():
    t = "fuzz_plane_vs_exact"
    base = [(0, 0, 0), (0, 0, 1), (1, 0, 0), (1, 1), (0.5, 0.5, 1), (0.5, 0.5, -1)]
    params = bytes([0x7C, 0x0F, 90])
    for name, flags, points in [
        ("crossing", 0, base),
        ("border", 0, base[:4] + [(1, 1, 1), (1, 1, -1)]),
        ("outside_by_a_little", 0, base[:4] + [(1 + 2.0 ** -50, 1, 1), (1, 1, -1)]),
        ("in_plane", 0, base[:4] + [(-2, 0.5, 0), (2, 0.5, 0)]),
        ("in_plane_corner", 0, base[:4] + [(2, 0, 0), (0, 2, 0)]),
        ("end_on_plane", 0, base[:4] + [(0.5, 0.5, 0), (3, 3, 3)]),
        ("point_on_plane", 0, base[:4] + [(0.5, 0.5, 0), (0.5, 0.5, 0)]),
        ("non_unit_skew_frame", 0, [(1, 2, 3), (0, 2, 1), (1, 1, 0), (0.5, 2), (1, 2, 4), (1, 2.5, 2)]),
        ("negative_extent", 0, base[:3] + [(-1, 1)] + base[4:]),
        ("zero_extent_hit", 0, base[:3] + [(0, 0)] + [(0, 0, 1), (0, 0, -1)]),
        ("axis_flags", 1, base), ("p1_on_plane", 2, base), ("p2_on_plane", 4, base), ("point", 8, base),
        ("mirror", 16, base), ("border_extent", 32, base), ("origin", 64, base), ("scaled", 128, base),
        ("all_planar", 2 | 4 | 1, base),
    ]:
        write(t, name, bytes([flags]) + coords(points) + params)


def selfcollide_seeds():
    t = "fuzz_selfcollide_continuous"
    # Two separate triangles; the second falls through the first.
    a = [(0, 0, 0), (2, 0, 0), (0, 2, 0)]
    b = [(0.5, 0.5, 1), (1, 0.25, -1), (0.25, 1, 1)]
    drop = [(0, 0, 0)] * 3 + [(0, 0, -2)] * 3
    tris = bytes([0, 1, 2, 3, 4, 5])
    write(t, "drop_through", bytes([2, 1, 0]) + tris + coords(a + b) + coords(drop))
    # Four triangles of a strip folding onto itself (shared vertices, neighbours' pairs).
    strip = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 2, 0), (1, 2, 0), (0, 0, 0), (0, 0, 0)]
    fold = [(0, 0, 0), (0, 0, 0), (0, 0, 0), (0, 0, 0), (0, -2, 1), (0, -2, 1), (0, 0, 0), (0, 0, 0)]
    strip_tris = bytes([0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4])
    write(t, "strip_fold", bytes([4, 3, 0]) + strip_tris + coords(strip) + coords(fold))
    # The same strip sliding in its own plane (coplanar throughout), and touching at the start.
    slide = [(0.5, 0.5, 0)] * 8
    write(t, "strip_coplanar_slide", bytes([4, 3, 2 | 4]) + strip_tris + coords(strip) + coords(slide))
    write(t, "touching_start", bytes([2, 1, 16]) + tris + coords(a + b) + coords(drop))
    # Edge-edge: two thin triangles whose edges cross at t = 1/2; x1 given on its own.
    c0 = [(0, 0, 0), (2, 0, 0), (1, 0, -1), (1, -1, 1), (1, 1, 1), (1, 0, 2)]
    c1 = [(0, 0, 0), (2, 0, 0), (1, 0, -1), (1, -1, -1), (1, 1, -1), (1, 0, 0)]
    write(t, "edges_cross", bytes([2, 1, 1]) + tris + coords(c0) + coords(c1))
    # One vertex moving, the rest still, onto an edge exactly at t = 1.
    write(t, "vertex_onto_edge", bytes([2, 1, 8]) + tris + coords(a + b) + coords([(0.5, -0.5, -1)] + [(0, 0, 0)] * 5))


if __name__ == "__main__":
    ccd_seeds()
    plane_seeds()
    selfcollide_seeds()
