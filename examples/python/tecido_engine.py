#!/usr/bin/env python3
"""An example tecido engine in Python (standard library only), spoken to in JSON lines:
`tecido ... --engine-cmd py=python3 examples/python/tecido_engine.py`, or called in-process by
tecido's Python module as the object Engine() (docs/python.md): `tecido.tri_tri(a, b,
engine=Engine())`, `tecido.suite(["tritri"], engines=[Engine()])`. Both doors run the same functions.

It answers these questions (see docs/engines.md, "Validate your own engine"):
  tri_tri   two closed triangles: does some edge of either cross the other (Moller-Trumbore
            without an epsilon, borders included)? It misses coplanar pairs (no edge crosses
            a plane it lies in) and decides touching cases in rounded arithmetic.
  ccd       vertex-face and edge-edge over t in [0, 1], points moving linearly: the four points
            are coplanar where a cubic in t vanishes; its roots in [0, 1] are found by
            bisection on the intervals where it is monotone (between the roots of its
            derivative; |cubic| within 1e-12 of its size counts as zero there, so a
            tangent touch is seen), and at the first root where the vertex lies in the triangle (the
            edges meet), within 1e-9 of their size, that is the time of impact. Motion
            coplanar throughout (a cubic that vanishes identically) is answered null: it
            cannot say.
  dynamics  particles and springs with gravity and linear drag, integrated by the explicit
            midpoint method (seed eqs. 6-8): global order 2, which hello claims.
and the batched forms of tri_tri and ccd, so that many queries cost one round trip.
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


def lerp(p0, p1, t):
    return [(1.0 - t) * a + t * b for a, b in zip(p0, p1)]


def coplanarity(p):
    """(p1 - p0) . ((p2 - p0) x (p3 - p0)): zero when the four points are coplanar."""
    return dot(sub(p[1], p[0]), cross(sub(p[2], p[0]), sub(p[3], p[0])))


def cubic(t0, t1):
    """Coefficients c0..c3 of the coplanarity of the moving points, from its values at 0, 1/3, 2/3, 1."""
    f = [coplanarity([lerp(a, b, s / 3.0) for a, b in zip(t0, t1)]) for s in range(4)]
    c0 = f[0]
    c1 = (-11.0 * f[0] + 18.0 * f[1] - 9.0 * f[2] + 2.0 * f[3]) / 2.0
    c2 = (18.0 * f[0] - 45.0 * f[1] + 36.0 * f[2] - 9.0 * f[3]) / 2.0
    c3 = (-9.0 * f[0] + 27.0 * f[1] - 27.0 * f[2] + 9.0 * f[3]) / 2.0
    return c0, c1, c2, c3, max(abs(x) for x in f)


def roots_in_unit(c0, c1, c2, c3, tol):
    """Real roots of c0 + c1 t + c2 t^2 + c3 t^3 in [0, 1], ascending: bisection on monotone pieces;
    an end of a piece where |f| <= tol counts as a root (a double root touches zero there)."""
    f = lambda t: ((c3 * t + c2) * t + c1) * t + c0
    cuts = [0.0, 1.0]
    a, b, c = 3.0 * c3, 2.0 * c2, c1  # the derivative a t^2 + b t + c
    d = b * b - 4.0 * a * c
    if a != 0.0 and d >= 0.0:
        q = -0.5 * (b + math.copysign(math.sqrt(d), b))  # the stable form: no cancellation
        if q != 0.0:
            cuts += [q / a, c / q]
        else:
            cuts.append(0.0)
    elif b != 0.0:
        cuts.append(-c / b)
    cuts = sorted(t for t in set(cuts) if 0.0 <= t <= 1.0)
    roots = []
    for lo, hi in zip(cuts, cuts[1:]):
        flo, fhi = f(lo), f(hi)
        if abs(flo) <= tol:
            roots.append(lo)
        elif flo * fhi < 0.0 and abs(fhi) > tol:
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                fm = f(mid)
                if (fm < 0.0) == (flo < 0.0):
                    lo, flo = mid, fm
                else:
                    hi = mid
            roots.append(hi)
    if abs(f(cuts[-1])) <= tol:
        roots.append(cuts[-1])
    return roots


def vertex_in_face(p, eps):
    e1, e2, d = sub(p[2], p[1]), sub(p[3], p[1]), sub(p[0], p[1])
    n = cross(e1, e2)
    nn = dot(n, n)
    if nn == 0.0:
        return False
    u = dot(cross(d, e2), n) / nn
    v = dot(cross(e1, d), n) / nn
    return u >= -eps and v >= -eps and u + v <= 1.0 + eps


def edges_meet(p, eps):
    a, b, r = sub(p[1], p[0]), sub(p[3], p[2]), sub(p[0], p[2])
    aa, ab, bb, ar, br = dot(a, a), dot(a, b), dot(b, b), dot(a, r), dot(b, r)
    den = aa * bb - ab * ab
    if den <= 1e-12 * aa * bb:
        return False  # parallel edges: not handled
    s = (ab * br - bb * ar) / den
    u = (aa * br - ab * ar) / den
    return -eps <= s <= 1.0 + eps and -eps <= u <= 1.0 + eps


def ccd(kind, t0, t1):
    """{"hit", "toi"} of one query; hit null when the motion is coplanar throughout."""
    c0, c1, c2, c3, size = cubic(t0, t1)
    if size == 0.0:
        return {"hit": None, "toi": None}
    meets = vertex_in_face if kind == "vertex-face" else edges_meet
    for t in roots_in_unit(c0, c1, c2, c3, 1e-12 * size):
        if meets([lerp(a, b, t) for a, b in zip(t0, t1)], 1e-9):
            return {"hit": True, "toi": t}
    return {"hit": False, "toi": None}


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


class Engine:
    """This engine as an object for tecido's Python module: the methods answer what the JSON-lines
    ops answer (docs/python.md, "Your engine in Python"), with the same functions."""

    name = "py"
    order = 2  # the midpoint method's global order, as hello claims

    def __init__(self):
        self.sim = None

    def tri_tri(self, a, b):
        return tri_tri(a, b)

    def tri_tri_batch(self, a, b):
        return [tri_tri(p, q) for p, q in zip(a.tolist(), b.tolist())]

    def ccd(self, kind, t0, t1):
        return ccd(kind, t0, t1)

    def ccd_batch(self, kinds, t0, t1):
        return [ccd(k, p, q) for k, p, q in zip(kinds, t0.tolist(), t1.tolist())]

    def create(self, scene, features):
        missing = [f for f in features if f not in MODELLED]
        if missing:
            return "not modelled: " + ", ".join(missing)
        self.sim = Midpoint(scene)
        return None

    def step(self, dt, steps):
        for _ in range(steps):
            self.sim.step(dt)
        return finite(self.sim.x), finite(self.sim.v)


def answer(req, state):
    op = req.get("op")
    if op == "hello":
        return {"protocol": 1, "supports": ["tri_tri", "tri_tri_batch", "ccd", "ccd_batch", "dynamics"], "order": 2}
    if op == "tri_tri":
        return {"hit": tri_tri(req["a"], req["b"])}
    if op == "tri_tri_batch":
        return {"results": [{"hit": tri_tri(q["a"], q["b"])} for q in req["queries"]]}
    if op == "ccd":
        return ccd(req["kind"], req["t0"], req["t1"])
    if op == "ccd_batch":
        return {"results": [ccd(q["kind"], q["t0"], q["t1"]) for q in req["queries"]]}
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
