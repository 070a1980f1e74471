#!/usr/bin/env python3
"""What the Python module's door costs, printed (docs/python.md, "Speed"; never asserted):

(a) tecido.tri_tri(a, b, "core") on 1e5 random pairs, per pair, against a plain C++ loop over the
    same pairs calling the same engine function (tecido._time_tri_tri), in the same run: the cost
    of the call, the array checks and copies, and the result array. Goal: ratio <= 2.
(b) The overhead per query of an engine written in Python (examples/python/tecido_engine.py)
    called in-process (tecido.tri_tri(a, b, engine=object)) against the same code behind the
    JSON-lines door (`tecido tritri --engine-cmd`), one query per call and batched. The overhead is
    measured with the engine's triangle test replaced by a constant (what remains is the door), and
    the whole query with the real test is printed too. The door's time per query is a difference
    of runs of N and 1 pairs, less the built-in core engine's difference (reading the pairs file and
    printing the answers), so process start and hello cancel. Goal: in-process >= 20x lower.
(c) tecido's side of a batch per answer, bools read directly against dicts read through a JSON reply.

Run from the repository's root: PYTHONPATH=build/python /usr/bin/python3 python/bench_overhead.py
[--tecido build/bin/tecido] [--pairs 100000] [--queries 2000]
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import tecido

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples" / "python"))
import tecido_engine  # noqa: E402

# The example engine behind the JSON-lines door, with its batched ops hidden (one query per line)
# and/or its triangle test replaced by a constant (the door's cost alone).
DOOR_SCRIPT = """import sys
sys.path.insert(0, {examples!r})
import tecido_engine
if {null!r}:
    tecido_engine.tri_tri = lambda a, b: False
answer = tecido_engine.answer
def answer_as_asked(req, state):
    reply = answer(req, state)
    if {unbatched!r} and req.get("op") == "hello":
        reply["supports"] = [s for s in reply["supports"] if not s.endswith("_batch")]
    return reply
tecido_engine.answer = answer_as_asked
tecido_engine.main()
"""


class Single:
    """The example engine's tri_tri, one call per query (`test`: its triangle test)."""
    name = "py"

    def __init__(self, test):
        self.test = test

    def tri_tri(self, a, b):
        return self.test(a, b)


class Batched(tecido_engine.Engine):
    """The example engine's batched form (`test`: its triangle test)."""

    def __init__(self, test):
        super().__init__()
        self.test = test

    def tri_tri_batch(self, a, b):
        return [self.test(p, q) for p, q in zip(a.tolist(), b.tolist())]


def never(a, b):
    return False


def best(f, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def pairs(n, seed):
    rng = np.random.default_rng(seed)
    return rng.random((n, 3, 3)), rng.random((n, 3, 3))


def vectorised(n, repeats):
    a, b = pairs(n, 1)
    print(f"(a) tri_tri on {n} random pairs in a unit cube, per pair (best of {repeats})")
    for engine in ("core", "exact"):
        py = best(lambda: tecido.tri_tri(a, b, engine), repeats) / n
        cpp = tecido._time_tri_tri(a, b, engine, repeats)
        print(f"    {engine:6s} tecido.tri_tri {py * 1e9:8.1f} ns   C++ loop {cpp * 1e9:8.1f} ns   ratio {py / cpp:5.2f}"
              + ("   (goal <= 2)" if engine == "core" else ""))


def run_cli(tecido_bin, path, engines, engine_cmd):
    args = [tecido_bin, "tritri", "--pairs", str(path), "--engines", engines, "--json"]
    if engine_cmd:
        args += ["--engine-cmd", engine_cmd]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)


def door_seconds(tecido_bin, files, engine_cmd, repeats):
    """Per extra query: (run of N - run of 1) / (N - 1), through the door, less the same for core."""
    (n, big), (_, one) = files
    t = {}
    for name, engines, cmd in (("door", "py", engine_cmd), ("core", "core", None)):
        tn = best(lambda: run_cli(tecido_bin, big, engines, cmd), repeats)
        t1 = best(lambda: run_cli(tecido_bin, one, engines, cmd), repeats)
        t[name] = (tn - t1) / (n - 1)
    return t["door"] - t["core"]


def in_process(n, tecido_bin, repeats):
    a, b = pairs(n, 2)
    al, bl = a.tolist(), b.tolist()
    own = best(lambda: [tecido_engine.tri_tri(p, q) for p, q in zip(al, bl)], repeats) / n
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="tecido-bench-"))
    files = []
    for k in (n, 1):
        path = tmp / f"pairs{k}.json"
        path.write_text(json.dumps({"pairs": [{"a": a[i].tolist(), "b": b[i].tolist()} for i in range(k)]}))
        files.append((k, path))
    print(f"(b) the example Python engine's tri_tri on {n} random pairs, per query (best of {repeats}); its own")
    print(f"    time per query, its function in a Python loop: {own * 1e6:.2f} us")
    for test, what in ((never, "overhead (the test replaced by a constant)"), (tecido_engine.tri_tri, "whole query (the real test)")):
        print(f"    {what}:")
        for label, engine, unbatched in (("one call per query", Single(test), True), ("batched", Batched(test), False)):
            script = tmp / f"door_{unbatched}_{test is never}.py"
            script.write_text(DOOR_SCRIPT.format(examples=str(ROOT / "examples" / "python"), null=test is never,
                                                 unbatched=unbatched))
            inproc = best(lambda: tecido.tri_tri(a, b, engine), repeats) / n
            door = door_seconds(tecido_bin, files, f"py={sys.executable} {script}", repeats)
            print(f"      {label:19s} in-process {inproc * 1e6:8.3f} us   JSON-lines door {door * 1e6:8.3f} us   "
                  f"door / in-process {door / inproc:6.1f}x" + ("   (goal >= 20x)" if test is never else ""))
            os.remove(script)
    for _, path in files:
        os.remove(path)
    os.rmdir(tmp)


class Canned:
    """A batched engine answering every batch with one prepared list (no work, no conversion in
    Python): what remains is tecido's side of a batch, building the arrays and reading the answers."""
    name = "canned"

    def __init__(self, answers):
        self.answers = answers

    def tri_tri_batch(self, a, b):
        return self.answers


def answer_reading(n, repeats):
    """(c) tecido's side of a batch per answer, in the same run: answers as Python bools or
    {"hit": bool} (read directly), as numpy bools (read through a JSON reply built from the value,
    the path a Python bool took before the direct reading) and as {"hit": numpy bool} (through the
    JSON text of the dict, the path a dict answer, e.g. the example's ccd, took before)."""
    a, b = pairs(n, 3)
    hits = [bool(k % 3 == 0) for k in range(n)]
    forms = (("bool", hits), ("{hit: bool}", [{"hit": h} for h in hits]), ("numpy bool", [np.bool_(h) for h in hits]),
             ("{hit: numpy bool}", [{"hit": np.bool_(h)} for h in hits]))
    print(f"(c) tecido's side of a batch of {n} answers, per answer (best of {repeats}):")
    base = None
    for form, answers in forms:
        t = best(lambda: tecido.tri_tri(a, b, Canned(answers)), repeats) / n
        base = base or t
        print(f"      {form:19s} {t * 1e6:8.3f} us   {t / base:6.1f}x the first")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--tecido", default=str(ROOT / "build" / "bin" / "tecido"))
    p.add_argument("--pairs", type=int, default=100000)
    p.add_argument("--queries", type=int, default=2000)
    p.add_argument("--repeats", type=int, default=5)
    o = p.parse_args()
    print(f"tecido {tecido.__version__} (commit {tecido.commit}), Python {sys.version.split()[0]}")
    vectorised(o.pairs, o.repeats)
    in_process(o.queries, o.tecido, max(3, o.repeats // 2))
    answer_reading(o.queries, o.repeats)


if __name__ == "__main__":
    main()
