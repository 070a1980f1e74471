"""tecido.self_collisions and continuous_self_collisions: meshes whose contacts are known by
construction, and the same meshes through `tecido selfcollide`."""
import json

import numpy as np
import pytest

import tecido

# Triangle 0 in z = 0; triangle 1 stands through its middle; triangle 2 far away.
V = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0],
              [0, -0.2, -1], [0, -0.2, 1], [0.3, 0.4, 0.5],
              [10, 10, 10], [11, 10, 10], [10, 11, 10]], dtype=np.float64)
F = np.array([[0, 1, 2], [3, 4, 5], [6, 7, 8]])


def write_obj(path, vertices, faces):
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices.tolist()]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces.tolist()]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("engine", ["core", "core-brute", "fcl", "exact"])
def test_pairs_by_construction(engine):
    pairs = tecido.self_collisions(V, F, engine)
    assert pairs.dtype == np.int64 and pairs.tolist() == [[0, 1]]


def test_same_pairs_as_the_command_line(tmp_path, cli):
    rng = np.random.default_rng(2)
    v = rng.random((300, 3))
    f = np.array([rng.choice(300, 3, replace=False) for _ in range(100)])
    out = json.loads(cli("selfcollide", "--mesh", write_obj(tmp_path / "m.obj", v, f), "--engines", "core,exact",
                         "--json").stdout)
    for engine in ("core", "exact"):
        assert tecido.self_collisions(v, f, engine).tolist() == out[engine]
    assert len(out["core"]) > 0


def test_a_vertex_through_a_face():
    # vertex 6 (of triangle 2) drops through triangle 0's interior; everything else stays
    v1 = V.copy()
    v0 = V.copy()
    v0[6] = [0.1, -0.5, 0.5]
    v1[6] = [0.1, -0.5, -0.5]
    v0[7:] = v1[7:] = [[20, 20, 20], [21, 20, 20]]
    for engine in ("core", "core-brute", "exact"):
        c = tecido.continuous_self_collisions(v0, v1, F, engine)
        assert [6, 0] in c["vertex_face"].tolist(), engine
        assert c["edge_edge"].shape[1:] == (2, 2)


def test_continuous_same_as_the_command_line(tmp_path, cli):
    rng = np.random.default_rng(4)
    v0 = rng.random((60, 3))
    v1 = v0 + rng.normal(scale=0.2, size=(60, 3))
    f = np.array([rng.choice(60, 3, replace=False) for _ in range(40)])
    out = json.loads(cli("selfcollide", "--mesh", write_obj(tmp_path / "a.obj", v0, f), "--to",
                         write_obj(tmp_path / "b.obj", v1, f), "--engines", "core,exact", "--json").stdout)
    for engine in ("core", "exact"):
        c = tecido.continuous_self_collisions(v0, v1, f, engine)
        assert c["vertex_face"].tolist() == out[engine]["vertex_face"]
        assert c["edge_edge"].tolist() == out[engine]["edge_edge"]
    assert out["exact"]["vertex_face"] or out["exact"]["edge_edge"]


def test_bad_meshes():
    with pytest.raises(ValueError, match=r"^F: /1/2: face names missing vertex 9 \(the mesh has 9 vertices"):
        tecido.self_collisions(V, np.array([[0, 1, 2], [3, 4, 9]]))
    with pytest.raises(ValueError, match=r"^F: /0/2: degenerate face: vertex 0 is repeated$"):
        tecido.self_collisions(V, np.array([[0, 1, 0]]))
    with pytest.raises(ValueError, match="F: dtype float64, expected integers"):
        tecido.self_collisions(V, F.astype(np.float64))
    with pytest.raises(ValueError, match=r"^V1: 8 vertices, but V0 has 9"):
        tecido.continuous_self_collisions(V, V[:8], F)
    with pytest.raises(ValueError, match=r'engine: unknown self-collision engine "fast"'):
        tecido.self_collisions(V, F, "fast")
