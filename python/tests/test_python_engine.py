"""A Python object as an engine, in-process: its answers, its errors (name and query), the GIL,
and the same engine through the JSON-lines door giving the same results."""
import json
import threading
import time

import numpy as np
import pytest

import tecido
import tecido_engine  # examples/python: the example engine, both doors
from conftest import ROOT
from test_ccd import arrays, edge_edge, vertex_face
from test_tri_tri import crossing_pair, random_pairs


class Single:
    """The example engine's functions without batched forms: one call per query."""
    name = "single"

    def tri_tri(self, a, b):
        return tecido_engine.tri_tri(a, b)

    def ccd(self, kind, t0, t1):
        return tecido_engine.ccd(kind, t0, t1)


@pytest.mark.parametrize("engine", [tecido_engine.Engine(), Single()], ids=["batched", "single"])
def test_answers_are_the_engines_own(engine):
    a, b = random_pairs(500, 21)
    expected = [tecido_engine.tri_tri(p, q) for p, q in zip(a.tolist(), b.tolist())]
    assert tecido.tri_tri(a, b, engine).tolist() == expected
    t0, t1 = arrays(vertex_face(1.0, -1.0), vertex_face(1.0, 0.5))
    hits, toi = tecido.ccd(t0, t1, "vf", engine)
    assert hits.tolist() == [True, False] and toi[0] == pytest.approx(0.5, abs=1e-9)
    t0, t1 = arrays(edge_edge(1.0, -3.0))
    hits, toi = tecido.ccd(t0, t1, "ee", engine)
    assert hits.tolist() == [True] and toi[0] == pytest.approx(0.25, abs=1e-9)


def test_the_exact_referee_judges_a_python_engine():
    a, b = random_pairs(2000, 8)
    exact = tecido.tri_tri(a, b, "exact")
    mine = tecido.tri_tri(a, b, tecido_engine.Engine())
    assert np.array_equal(mine, exact)  # generic pairs: no coplanar or touching case


class Raises:
    name = "boom"

    def tri_tri(self, a, b):
        if a[0][0] > 0.5:
            raise ZeroDivisionError("my bug")
        return False


def test_an_exception_names_the_engine_and_the_query():
    a = np.zeros((4, 3, 3))
    a[2, 0, 0] = 1.0
    with pytest.raises(tecido.EngineError) as e:
        tecido.tri_tri(a, np.zeros((4, 3, 3)), Raises())
    msg = str(e.value)
    assert msg.startswith("engine boom (Python object ")
    assert "query 2 (tri_tri): ZeroDivisionError: my bug" in msg
    assert isinstance(e.value.__cause__, ZeroDivisionError)
    assert isinstance(e.value, RuntimeError)


def test_an_exception_inside_a_suite_reaches_the_caller():
    """Raised on a suite's worker thread, it crosses the C++ sweep and comes back with its cause."""
    with pytest.raises(tecido.EngineError) as e:
        tecido.suite("tritri", engines=[Raises()], quick=True, threads=2)
    assert str(e.value).startswith("engine boom (Python object ")
    assert "ZeroDivisionError: my bug" in str(e.value)
    assert isinstance(e.value.__cause__, ZeroDivisionError)


class Liar:
    name = "liar"

    def tri_tri_batch(self, a, b):
        return ["yes"] * len(a)

    def ccd(self, kind, t0, t1):
        return ("maybe", 0.5)


def test_answers_outside_the_protocol_are_engine_errors():
    with pytest.raises(tecido.EngineError, match=r"engine liar .*query 0 \(tri_tri_batch\): .*str"):
        tecido.tri_tri(np.zeros((2, 3, 3)), np.zeros((2, 3, 3)), Liar())
    t0, t1 = arrays(vertex_face(1.0, -1.0))
    with pytest.raises(tecido.EngineError, match=r"engine liar .*query 0 \(ccd\)"):
        tecido.ccd(t0, t1, "vf", Liar())


def test_objects_that_cannot_be_engines():
    with pytest.raises(ValueError, match="none of the methods"):
        tecido.tri_tri(np.zeros((1, 3, 3)), np.zeros((1, 3, 3)), object())

    class Core(Single):
        name = "core"

    with pytest.raises(ValueError, match='engine name "core" is a built-in engine\'s'):
        tecido.tri_tri(np.zeros((1, 3, 3)), np.zeros((1, 3, 3)), Core())

    class OnlyTriTri:
        def tri_tri(self, a, b):
            return True

    t0, t1 = arrays(vertex_face(1.0, -1.0))
    with pytest.raises(ValueError, match="does not answer ccd queries"):
        tecido.ccd(t0, t1, "vf", OnlyTriTri())


def test_long_calls_release_the_gil():
    """A Python thread keeps counting while run() works in C++ (it would stop if the GIL were held)."""
    count = [0]
    stop = threading.Event()

    def counter():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=counter)
    t.start()
    try:
        time.sleep(0.05)
        before = count[0]
        start = time.perf_counter()
        tecido.run(str(ROOT / "data" / "scenes" / "long_run_cloth.json"), steps=3000)
        seconds = time.perf_counter() - start
        during = count[0] - before
    finally:
        stop.set()
        t.join()
    assert seconds > 0.1, "the call was too short to tell"
    assert during > 10000, f"the thread counted {during} times in {seconds:.2f} s"


def test_a_python_engine_in_a_suite_equals_the_json_lines_door(tmp_path, cli, engine_cmd):
    """tecido.suite with the object Engine() and `tecido suite` with the same code behind
    --engine-cmd: the same checks and the same data, door and timings aside."""
    report = tecido.suite(["tritri", "ccd"], engines=["core", tecido_engine.Engine()], quick=True, threads=2)
    out = tmp_path / "door"
    cli("suite", "tritri", "ccd", "--quick", "--threads", "2", "--engines", "core,py", "--engine-cmd", engine_cmd,
        "--out", out, check=False)
    door = json.loads((out / "report.json").read_text())
    assert comparable(report) == comparable(door)
    assert "py" in json.dumps(report["suites"])


def test_a_python_engine_simulates_in_a_suite_as_through_the_door(tmp_path, cli, engine_cmd):
    """create/step in-process: the order suite measures the example's midpoint integrator (order
    2, which it claims) alike through both doors."""
    report = tecido.suite("order", engines=[tecido_engine.Engine()], quick=True, threads=2)
    out = tmp_path / "door"
    cli("suite", "order", "--quick", "--threads", "2", "--engines", "py", "--engine-cmd", engine_cmd, "--out", out,
        check=False)
    door = json.loads((out / "report.json").read_text())
    assert comparable(report) == comparable(door)
    checks = [c for s in report["suites"] for c in s["checks"] if "py" in c["name"]]
    assert checks and all(c["pass"] for c in checks), checks


# what differs by door or run: timings, the door's description, whether it is a process
TIMING = ("seconds", "ns_per", "cost", "time_", "_time", "door", "command_line", "per_query", "wall", "cpu", "process")


def comparable(doc):
    """The report without what differs between runs and doors: timings, the door's description,
    the provenance."""
    if isinstance(doc, dict):
        return {k: comparable(v) for k, v in doc.items()
                if k != "tecido" and not any(t in k for t in TIMING)}
    if isinstance(doc, list):
        return [comparable(v) for v in doc]
    return doc


class Forms:
    """Answers in every form the protocol allows: plain (read directly) and others (read through a
    JSON reply, as the door reads them); each form must mean the same."""
    name = "forms"
    HITS = [True, np.bool_(True), {"hit": True}, (True,), False, np.bool_(False), {"hit": False}]
    CCD = [{"hit": True, "toi": 0.25}, (True, 0.25), [True, 0.25], {"hit": True, "toi": np.float64(0.25)},
           {"toi": 0.25, "hit": True}, {"hit": False, "toi": None}, (False, 0.75), {"hit": False, "toi": 1}]

    def tri_tri_batch(self, a, b):
        return self.HITS

    def ccd_batch(self, kinds, t0, t1):
        return self.CCD


class LateToi:
    name = "late-toi"

    def ccd_batch(self, kinds, t0, t1):
        return [(True, None)]


def test_every_form_of_an_answer_means_the_same():
    n = len(Forms.HITS)
    assert tecido.tri_tri(np.zeros((n, 3, 3)), np.zeros((n, 3, 3)), Forms()).tolist() == [True] * 4 + [False] * 3
    t0, t1 = arrays(*[vertex_face(1.0, -1.0)] * len(Forms.CCD))
    hits, toi = tecido.ccd(t0, t1, "vf", Forms())
    assert hits.tolist() == [True] * 5 + [False] * 3
    assert toi[:5].tolist() == [0.25] * 5
    with pytest.raises(tecido.EngineError, match=r"engine late-toi .*query 0 \(ccd_batch\): .*toi"):
        tecido.ccd(*arrays(vertex_face(1.0, -1.0)), "vf", LateToi())
