"""tecido.tri_tri against independent truth: triangles that cross or miss by construction, the
exact referee on random pairs, the command line on the same pairs."""
import json

import numpy as np
import pytest

import tecido
from conftest import write_json


def crossing_pair():
    """b pierces a: a lies in z = 0 around the origin, b stands vertically through its middle."""
    a = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]]
    b = [[0.0, -0.2, -1.0], [0.0, -0.2, 1.0], [0.3, 0.4, 0.5]]
    return a, b


def test_crossing_and_separated_by_construction():
    a, b = crossing_pair()
    far = (np.array(b) + [0.0, 0.0, 5.0]).tolist()  # lifted 5 m: entirely above a's plane
    A = np.array([a, a], dtype=np.float64)
    B = np.array([b, far], dtype=np.float64)
    for engine in ("core", "exact", "fcl"):
        assert tecido.tri_tri(A, B, engine).tolist() == [True, False], engine


def test_touching_counts():
    a, _ = crossing_pair()
    # shares the vertex (1, -1, 0) and lies above the plane otherwise
    b = [[1.0, -1.0, 0.0], [2.0, -1.0, 1.0], [2.0, 0.0, 1.0]]
    assert tecido.tri_tri(np.array([a]), np.array([b]), "exact").tolist() == [True]


def random_pairs(n, seed):
    rng = np.random.default_rng(seed)
    return rng.random((n, 3, 3)), rng.random((n, 3, 3)) + 0.1


def test_core_agrees_with_the_exact_referee_on_random_pairs():
    a, b = random_pairs(20000, 7)
    exact = tecido.tri_tri(a, b, "exact")
    core = tecido.tri_tri(a, b, "core")
    assert 0.1 < exact.mean() < 0.9  # both answers occur
    assert np.array_equal(core, exact)


def test_same_answers_as_the_command_line(tmp_path, cli):
    a, b = random_pairs(300, 11)
    pairs = [{"id": str(i), "a": a[i].tolist(), "b": b[i].tolist()} for i in range(len(a))]
    path = write_json(tmp_path / "pairs.json", {"pairs": pairs})
    rows = json.loads(cli("tritri", "--pairs", path, "--engines", "core,exact,ccd-gjk", "--json").stdout)["results"]
    for engine in ("core", "exact", "ccd-gjk"):
        assert tecido.tri_tri(a, b, engine).tolist() == [r[engine] for r in rows], engine


def test_strided_input_is_read_in_place():
    a, b = random_pairs(1000, 3)
    wide_a = np.zeros((1000, 3, 6))
    wide_a[:, :, ::2] = a  # every other column: a non-contiguous view
    view = wide_a[:, :, ::2]
    assert not view.flags["C_CONTIGUOUS"]
    assert np.array_equal(tecido.tri_tri(view, b), tecido.tri_tri(a, b))
    assert np.array_equal(tecido.tri_tri(a[::-1], b[::-1]), tecido.tri_tri(a, b)[::-1])


def test_lists_of_floats_are_accepted():
    a, b = crossing_pair()
    assert tecido.tri_tri([a], [b]).tolist() == [True]


def test_empty_input():
    empty = np.zeros((0, 3, 3))
    assert tecido.tri_tri(empty, empty).shape == (0,)


@pytest.mark.parametrize(
    "a, message",
    [
        (np.zeros((2, 3, 3), dtype=np.float32), "a: dtype float32, expected float64"),
        (np.zeros((2, 3, 3), dtype=np.int64), "a: dtype int64, expected float64"),
        ([[[0, 0, 0], [1, 0, 0], [0, 1, 0]]] * 2, "a: dtype int64, expected float64"),
        (np.zeros((2, 3, 2)), "a: expected an array of shape (N, 3, 3), got shape (2, 3, 2)"),
        (np.zeros((2, 9)), "a: expected an array of shape (N, 3, 3), got shape (2, 9)"),
    ],
)
def test_wrong_dtype_or_shape_is_a_value_error(a, message):
    with pytest.raises(ValueError) as e:
        tecido.tri_tri(a, np.zeros((2, 3, 3)))
    assert str(e.value).startswith(message)


def test_non_finite_and_out_of_range_coordinates_name_their_place():
    a = np.zeros((4, 3, 3))
    a[3, 1, 2] = np.nan
    with pytest.raises(ValueError, match=r"^a: /3/1/2: number is not finite \(nan\)$"):
        tecido.tri_tri(a, np.zeros((4, 3, 3)))
    b = np.zeros((4, 3, 3))
    b[0, 2, 0] = 1e16
    with pytest.raises(ValueError, match=r"^b: /0/2/0: number 1e\+16 is out of range \(\|x\| <= 1e\+15\)$"):
        tecido.tri_tri(np.zeros((4, 3, 3)), b)


def test_count_mismatch_and_unknown_engine():
    with pytest.raises(ValueError, match="b: 2 queries, but a has 3"):
        tecido.tri_tri(np.zeros((3, 3, 3)), np.zeros((2, 3, 3)))
    with pytest.raises(ValueError, match=r'engine: unknown tri-tri engine "nope" \(known: core, '):
        tecido.tri_tri(np.zeros((1, 3, 3)), np.zeros((1, 3, 3)), "nope")


def test_engine_names_are_the_command_lines():
    names = tecido.engines("tri_tri")
    assert names[0] == "core" and "exact" in names
    assert "exact" in tecido.engines("ccd")
