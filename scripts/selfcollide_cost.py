#!/usr/bin/env python3
"""Times the whole `tecido selfcollide` process on a real-sized mesh: continuous (two frames) against
discrete (the end frame), and the continuous command on 1 and more threads. Ratios in one run.

    python3 scripts/selfcollide_cost.py [--tecido build/bin/tecido] [--n 256] [--rounds 5] [--threads 1,2]

The frames are those of scripts/fold_frames.py (an N x N cloth folding onto itself, 2 (N - 1)^2
triangles), written to a temporary directory. Each round runs, in turn (the order rotating from round
to round, so that a machine growing busier penalises none), `selfcollide --mesh T1` (discrete, engine
core) and `selfcollide --mesh T0 --to T1 --threads t` for each t; the figures are the medians of the
rounds' wall times (OBJ parsing and JSON output included, as a user sees it). The continuous answers at
every thread count must be byte-identical (the script stops otherwise).
"""
import argparse
import hashlib
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fold_frames  # noqa: E402


def timed(cmd):
    """Wall seconds of one run of cmd, and the SHA-256 of its stdout."""
    t0 = time.perf_counter()
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE).stdout
    return time.perf_counter() - t0, hashlib.sha256(out).hexdigest(), len(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--tecido", default="build/bin/tecido")
    p.add_argument("--n", type=int, default=256)
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--threads", default="1,2")
    a = p.parse_args()
    threads = [int(t) for t in a.threads.split(",")]
    with tempfile.TemporaryDirectory() as d:
        t0 = os.path.join(d, f"fold_{a.n}_t0.obj")
        t1 = os.path.join(d, f"fold_{a.n}_t1.obj")
        fold_frames.write_frame(t0, a.n, 0.04, 0.0)
        fold_frames.write_frame(t1, a.n, 0.02, 0.01)
        runs = [("discrete", [a.tecido, "selfcollide", "--mesh", t1, "--threads", "1", "--json"])]
        for t in threads:
            runs.append((f"continuous/threads:{t}",
                         [a.tecido, "selfcollide", "--mesh", t0, "--to", t1, "--threads", str(t), "--json"]))
        times = {name: [] for name, _ in runs}
        digests = {}
        for r in range(a.rounds):
            order = runs[r % len(runs):] + runs[:r % len(runs)]
            for name, cmd in order:
                s, digest, size = timed(cmd)
                times[name].append(s)
                digests.setdefault(name, (digest, size))
            print(f"round {r + 1} of {a.rounds} done", file=sys.stderr)
    answers = {digests[name] for name, _ in runs if name.startswith("continuous")}
    if len(answers) != 1:
        sys.exit("selfcollide_cost.py: the continuous answers differ between thread counts")
    triangles = 2 * (a.n - 1) ** 2
    med = {name: statistics.median(v) for name, v in times.items()}
    print(f"mesh: {a.n} x {a.n} folding cloth, {triangles} triangles; medians of {a.rounds} interleaved rounds (wall s)")
    for name, _ in runs:
        print(f"  {name:<24} {med[name]:8.3f} s   ({med[name] / med['discrete']:.2f}x discrete)")
    one = f"continuous/threads:{threads[0]}"
    for t in threads[1:]:
        print(f"  speed-up of {t} threads over {threads[0]}: {med[one] / med[f'continuous/threads:{t}']:.2f}x")
    print(f"  continuous answers byte-identical at threads {a.threads} ({next(iter(answers))[1]} bytes)")


if __name__ == "__main__":
    main()
