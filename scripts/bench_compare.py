#!/usr/bin/env python3
"""Compares two builds of tecido-bench in one run: ratios, not absolute times.

    python3 scripts/bench_compare.py BASE_BIN HEAD_BIN [--filter REGEX] [--rounds N] [--min-time S]

Runs the two binaries in turn, N rounds (the order alternating from round to round, so that a
machine growing busier or cooler penalises neither), each on the benchmarks matching REGEX, and
prints per benchmark the median CPU time of each and head/base. A ratio above 1 is head slower.
The medians of interleaved rounds, not one run each: on a shared machine a single run of either
can land on a busy second.
"""
import argparse
import json
import statistics
import subprocess
import sys


def run(binary, regex, min_time):
    """CPU time (ns) per benchmark of one run of `binary`."""
    out = subprocess.run([binary, "--benchmark_format=json", f"--benchmark_filter={regex}",
                          f"--benchmark_min_time={min_time}"], check=True, capture_output=True, text=True).stdout
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    return {b["name"]: b["cpu_time"] * scale[b.get("time_unit", "ns")]
            for b in json.loads(out)["benchmarks"] if b.get("run_type", "iteration") == "iteration"}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("base")
    p.add_argument("head")
    p.add_argument("--filter", default=".")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--min-time", default="0.2")
    a = p.parse_args()
    times = {"base": {}, "head": {}}
    for r in range(a.rounds):
        order = [("base", a.base), ("head", a.head)]
        for side, binary in (order if r % 2 == 0 else order[::-1]):
            for name, t in run(binary, a.filter, a.min_time).items():
                times[side].setdefault(name, []).append(t)
        print(f"round {r + 1} of {a.rounds} done", file=sys.stderr)
    names = [n for n in times["head"] if n in times["base"]]
    width = max(len(n) for n in names) if names else 10
    print(f"{'benchmark':<{width}}  {'base ns':>12}  {'head ns':>12}  head/base")
    for n in names:
        b, h = statistics.median(times["base"][n]), statistics.median(times["head"][n])
        print(f"{n:<{width}}  {b:12.1f}  {h:12.1f}  {h / b:9.3f}")
    only = sorted(set(times["base"]) ^ set(times["head"]))
    if only:
        print("in one build only: " + ", ".join(only))


if __name__ == "__main__":
    main()
