#!/usr/bin/env python3
"""An example tecido engine in Python (standard library only), spoken to in JSON lines:
`tecido ... --engine-cmd py=python3 examples/python/tecido_engine.py`.

It answers three questions (see README, "Validate your own engine"):
  tri_tri   two closed triangles: does some edge of either cross the other (Moller-Trumbore
            without an epsilon, borders included)? It misses coplanar pairs (no edge crosses
            a plane it lies in) and decides touching cases in rounded arithmetic.
  dynamics  particles and springs with gravity and linear drag, integrated by the explicit
            midpoint method (seed eqs. 6-8): global order 2, which hello claims.
and the batched form of tri_tri, so that many pairs cost one round trip.
"""
import json
import math
import sys


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def segment_hits(o, d, tri):
    """The segment o -> o + d against the closed triangle tri (Moller-Trumbore, no epsilon)."""
    e1, e2 = sub(tri[1], tri[0]), sub(tri[2], tri[0])
    p = cross(d, e2)
    det = dot(e1, p)
    if det == 0.0:
        return False  # parallel to the plane (coplanar pairs are missed)
    tv = sub(o, tri[0])
    u = dot(tv, p) / det
    if u < 0.0 or u > 1.0:
        return False
    q = cross(tv, e1)
    v = dot(d, q) / det
    if v < 0.0 or u + v > 1.0:
        return False
    t = dot(e2, q) / det
    return 0.0 <= t <= 1.0


def tri_tri(a, b):
    for s, t in ((a, b), (b, a)):
        for i in range(3):
            if segment_hits(s[i], sub(s[(i + 1) % 3], s[i]), t):
                return True
    return False


class Midpoint:
    """x' = v, v' = g - (c/m) v + springs/m; pinned particles (no mass) never move."""

    def __init__(self, scene):
        ps = scene["particles"]
        self.x = [list(p["position"]) for p in ps]
        self.v = [list(p.get("velocity", [0, 0, 0])) for p in ps]
        self.w = [0.0 if p.get("pinned") else 1.0 / p["mass"] for p in ps]
        self.springs = [(s["i"], s["j"], s["stiffness"], s["rest_length"]) for s in scene.get("springs", [])]
        self.g = scene.get("gravity", [0.0, 0.0, 0.0])
        self.c = scene.get("air_drag", 0.0)

    def accel(self, x, v):
        f = [[0.0, 0.0, 0.0] for _ in x]
        for i, j, k, l in self.springs:
            d = sub(x[j], x[i])
            n = math.sqrt(dot(d, d))
            if n > 0.0:
                s = k * (n - l) / n
                for c in range(3):
                    f[i][c] += s * d[c]
                    f[j][c] -= s * d[c]
        return [[0.0] * 3 if w == 0.0 else [self.g[c] + w * (f[i][c] - self.c * v[i][c]) for c in range(3)]
                for i, w in enumerate(self.w)]

    def step(self, h):
        x, v = self.x, self.v
        a = self.accel(x, v)
        xm = [[x[i][c] + 0.5 * h * v[i][c] for c in range(3)] for i in range(len(x))]
        vm = [[v[i][c] + 0.5 * h * a[i][c] for c in range(3)] for i in range(len(x))]
        am = self.accel(xm, vm)
        self.x = [[x[i][c] + h * vm[i][c] for c in range(3)] for i in range(len(x))]
        self.v = [[v[i][c] + h * am[i][c] for c in range(3)] for i in range(len(x))]


def finite(points):
    return [[c if math.isfinite(c) else None for c in p] for p in points]


MODELLED = set()  # features beyond particles, springs, gravity and drag: none


def answer(req, state):
    op = req.get("op")
    if op == "hello":
        return {"supports": ["tri_tri", "tri_tri_batch", "dynamics"], "order": 2}
    if op == "tri_tri":
        return {"hit": tri_tri(req["a"], req["b"])}
    if op == "tri_tri_batch":
        return {"results": [{"hit": tri_tri(q["a"], q["b"])} for q in req["queries"]]}
    if op == "create":
        missing = [f for f in req.get("features", []) if f not in MODELLED]
        if missing:
            return {"error": "not modelled: " + ", ".join(missing)}
        state["sim"] = Midpoint(req["scene"])
        return {"ok": True}
    if op == "step":
        sim = state["sim"]
        for _ in range(req["steps"]):
            sim.step(req["dt"])
        return {"x": finite(sim.x), "v": finite(sim.v)}
    return {"error": "unknown op %r" % op}


def main():
    state = {}
    for line in sys.stdin:
        reply = answer(json.loads(line), state)
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
