"""tecido.ccd against analytic motions (a point moving onto a face, edges crossing, at known
times), the exact referee, and the command line on the same queries."""
import json

import numpy as np
import pytest

import tecido
from conftest import write_json

FACE = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


def vertex_face(z0, z1, x=0.2, y=0.2):
    """A vertex moving straight down from height z0 to z1 over the static face FACE (in z = 0)."""
    return [[x, y, z0]] + FACE, [[x, y, z1]] + FACE


def edge_edge(z0, z1):
    """Edge a along x at height z0 -> z1; edge b static along y in z = 0: they cross at (0, 0, 0)."""
    b = [[0.0, -1.0, 0.0], [0.0, 1.0, 0.0]]
    return [[-1.0, 0.0, z0], [1.0, 0.0, z0]] + b, [[-1.0, 0.0, z1], [1.0, 0.0, z1]] + b


def arrays(*queries):
    return np.array([q[0] for q in queries]), np.array([q[1] for q in queries])


@pytest.mark.parametrize("engine", ["core", "exact", "fcl"])  # bullet misses these (as `tecido ccd` shows)
def test_vertex_onto_face_at_known_times(engine):
    # contact when z(t) = z0 + t (z1 - z0) = 0: t = 1/2, 1/4, 1 (touching at the end), never
    t0, t1 = arrays(vertex_face(1.0, -1.0), vertex_face(1.0, -3.0), vertex_face(1.0, 0.0), vertex_face(1.0, 0.5),
                    vertex_face(1.0, -1.0, x=2.0))
    hits, toi = tecido.ccd(t0, t1, "vf", engine)
    assert hits.tolist() == [True, True, True, False, False]
    tol = 0 if engine == "exact" else 1e-4  # the floating engines' time tolerances (docs/limits.md)
    assert toi[:3] == pytest.approx([0.5, 0.25, 1.0], abs=tol)
    assert np.isnan(toi[3:]).all()


@pytest.mark.parametrize("engine", ["core", "exact"])
def test_edges_crossing_at_known_times(engine):
    t0, t1 = arrays(edge_edge(1.0, -1.0), edge_edge(2.0, -2.0), edge_edge(1.0, 0.25))
    hits, toi = tecido.ccd(t0, t1, "edge-edge", engine)
    assert hits.tolist() == [True, True, False]
    assert toi[:2] == pytest.approx([0.5, 0.5], abs=0 if engine == "exact" else 1e-6)


def test_an_engine_without_an_answer():
    t0, t1 = arrays(edge_edge(1.0, -1.0))
    with pytest.raises(ValueError, match="engine bullet gives no answer to query 0"):
        tecido.ccd(t0, t1, "ee", "bullet")
    hits, toi, answered = tecido.ccd(t0, t1, "ee", "bullet", answered=True)
    assert answered.tolist() == [False] and hits.tolist() == [False] and np.isnan(toi[0])


def test_same_answers_as_the_command_line(tmp_path, cli):
    rng = np.random.default_rng(5)
    t0 = rng.random((200, 4, 3))
    t1 = t0 + rng.normal(scale=0.5, size=(200, 4, 3))
    queries = [{"id": str(i), "kind": "vertex-face", "t0": t0[i].tolist(), "t1": t1[i].tolist()} for i in range(200)]
    path = write_json(tmp_path / "q.json", {"queries": queries})
    rows = json.loads(cli("ccd", "--queries", path, "--engines", "core,exact", "--json").stdout)["results"]
    for engine in ("core", "exact"):
        hits, toi = tecido.ccd(t0, t1, "vf", engine)
        assert hits.tolist() == [r[engine]["hit"] for r in rows]
        assert [None if np.isnan(t) else t for t in toi] == [r[engine]["toi"] for r in rows]
    assert 0 < sum(r["exact"]["hit"] for r in rows) < 200


def test_bad_input():
    t0, t1 = arrays(vertex_face(1.0, -1.0))
    with pytest.raises(ValueError, match=r'kind: expected "vf" \(vertex-face\) or "ee" \(edge-edge\), got "fv"'):
        tecido.ccd(t0, t1, "fv")
    bad = t1.copy()
    bad[0, 3, 1] = np.inf
    with pytest.raises(ValueError, match=r"^t1: /0/3/1: number is not finite \(inf\)$"):
        tecido.ccd(t0, bad, "vf")
    with pytest.raises(ValueError, match=r"t0: expected an array of shape \(N, 4, 3\), got shape \(1, 3, 3\)"):
        tecido.ccd(t0[:, :3], t1, "vf")
