#!/usr/bin/env python3
"""Writes two consecutive frames of an n x n cloth folding onto itself as Wavefront OBJ files.

    python3 scripts/fold_frames.py N OUT_DIR

OUT_DIR/fold_<N>_t0.obj and fold_<N>_t1.obj: a square of side 1 m, (N - 1)^2 quads cut into two
triangles each (2 (N - 1)^2 triangles: 130050 at N = 256), folded over itself along x = 0.5 (a
half-turn bend of radius H / 2, the flap's flat part at height H) with a ripple of amplitude
0.03 m (sin(9u + 1) sin 7v) on both layers, so the layers cross along curves. Between the frames
the fold closes from H = 0.04 m to H = 0.02 m while the whole cloth falls 1 cm: the step of
bench/bench_continuous_self_collision.cpp (a fast fold, 1.2 m/s at 60 Hz; the layers pass through
each other over a wide band), written so that `tecido selfcollide --mesh T0 --to T1` can be timed
on a real-sized mesh as a user runs it. Coordinates are written with 17 significant digits (the
doubles round-trip). Deterministic: same N, same files.
"""
import math
import os
import sys


def folded(u, v, h, drop):
    """The point of rest position (u, v) on the cloth folded with flap height h, lowered by drop."""
    r = 0.5 * h
    ripple = 0.03 * math.sin(9.0 * u + 1.0) * math.sin(7.0 * v)
    if u <= 0.5:
        return (u, v, ripple - drop)
    a = (u - 0.5) / r
    if a < math.pi:
        return (0.5 + r * math.sin(a), v, r - r * math.cos(a) + ripple - drop)
    return (0.5 - (u - 0.5 - math.pi * r), v, h - ripple - drop)


def write_frame(path, n, h, drop):
    step = 1.0 / (n - 1)
    lines = []
    for i in range(n):
        for j in range(n):
            x, y, z = folded(j * step, i * step, h, drop)
            lines.append(f"v {x:.17g} {y:.17g} {z:.17g}\n")
    for i in range(n - 1):
        for j in range(n - 1):
            a = i * n + j + 1  # OBJ indices are 1-based
            b, c, d = a + 1, a + n, a + n + 1
            lines.append(f"f {a} {b} {d}\nf {a} {d} {c}\n")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.writelines(lines)
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: fold_frames.py N OUT_DIR")
    n = int(sys.argv[1])
    if n < 2:
        sys.exit("fold_frames.py: N must be at least 2")
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    write_frame(os.path.join(out, f"fold_{n}_t0.obj"), n, 0.04, 0.0)
    write_frame(os.path.join(out, f"fold_{n}_t1.obj"), n, 0.02, 0.01)
    print(os.path.join(out, f"fold_{n}_t0.obj"), os.path.join(out, f"fold_{n}_t1.obj"))


if __name__ == "__main__":
    main()
