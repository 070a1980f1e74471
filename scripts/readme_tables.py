#!/usr/bin/env python3
"""README.md's generated blocks: the experiments' verdict tables and the speed goals, from committed results.

The block between the marker comments
    <!-- self-contact-verdicts:begin -->  ...  <!-- self-contact-verdicts:end -->
is rewritten from the self-contact result (default docs/results/self_contact_experiment.json), and
the block between
    <!-- forced-contact-verdicts:begin -->  ...  <!-- forced-contact-verdicts:end -->
from the forced-contact result (default docs/results/forced_contact/experiment.json), and the block
between
    <!-- speed-goals:begin -->  ...  <!-- speed-goals:end -->
from the goals of a `tecido suite bench` report (default docs/results/bench/report.json); nothing
else of the README is touched. With --check nothing is written: the exit code is 1 when the README's
block differs from what the file gives (a unified diff on stderr), 0 when it is the same.
Bad input (a missing file, a file that is not an experiment result, no markers): one line on
stderr naming the file and the problem, exit 2, nothing written.

    python3 scripts/readme_tables.py            # rewrite README.md's block
    python3 scripts/readme_tables.py --check    # the test (tests/comparisons/cli/test_readme_tables.cpp)
"""
import argparse
import difflib
import json
import math
import os
import sys
import tempfile
import textwrap

BEGIN = "<!-- self-contact-verdicts:begin -->"
END = "<!-- self-contact-verdicts:end -->"
FORCED_BEGIN = "<!-- forced-contact-verdicts:begin -->"
FORCED_END = "<!-- forced-contact-verdicts:end -->"
SPEED_BEGIN = "<!-- speed-goals:begin -->"
SPEED_END = "<!-- speed-goals:end -->"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED_CLAIMS = ["mode3-better", "mode3-size", "mode3-wind", "mode2-worse", "mode1-marginal"]
CHECKS = ["mode3-every-step", "mode3-every-elasticity", "elasticity-level", "step-level", "cells-match"]
PREMISE = ["premise-border", "premise-gia-fails"]
COST = ["rotation-slower-than-mt", "detection-dominates-step", "detection-dominates-step-bvh"]
SHORT = {"reproduced": "R", "not reproduced": "N", "inconclusive": "?"}


class InputProblem(Exception):
    """A one-line problem with an input file."""


def value(claim, x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "n/a"
    unit = claim["unit"]
    if unit in ("relative change", "difference of relative changes"):
        return f"{100.0 * x:+.1f}%"
    if unit == "ratio":
        return f"{x:.2f}"
    return f"{x:.3f}"


def ours(claim):
    lo, hi = claim["ci95"]
    return f"{value(claim, claim['observed'])} [{value(claim, lo)}, {value(claim, hi)}]"


def p_text(p):
    return "n/a" if p is None else f"{p:.2g}"


def verdict(claim):
    v = claim["verdict"]
    if v == "reproduced":
        return f"reproduced (p {p_text(claim['p_support_holm'])})"
    if v == "not reproduced":
        return f"**not reproduced** (p {p_text(claim['p_refute_holm'])})"
    return "inconclusive" + (" (no variation)" if claim["reason"].startswith("no variation") else "")


def seed_value(claim):
    if claim["seed"] is None:
        return claim["seed_text"].split(";")[0]
    return value(claim, claim["seed"])


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise InputProblem(f"{path}: cannot read: {e.strerror}")
    except json.JSONDecodeError as e:
        raise InputProblem(f"{path}: line {e.lineno}: not JSON: {e.msg}")


class Result:
    def __init__(self, path):
        self.path = path
        self.doc = read_json(path)
        if not isinstance(self.doc, dict) or self.doc.get("experiment") != "self-contact" or "claims" not in self.doc:
            raise InputProblem(f"{path}: /experiment: not a self-contact experiment result")
        self.detectors = self.doc["detectors"]

    def claim(self, cid, detector=None):
        for c in self.doc["claims"]:
            if c["id"] == cid and c["detector"] == detector:
                return c
        raise InputProblem(f"{self.path}: /claims: no claim \"{cid}\" for detector {detector}")

    def strengths(self):
        """(strength in N, variant id) of the baseline and the push variants, ascending."""
        out = [(self.doc["strength"], "baseline")]
        for v in self.doc["sensitivity"]["variants"]:
            if v["choice"] == "push strength":
                out.append((v["interpretation"]["strength"], v["id"]))
        return sorted(out)

    def row_verdict(self, variant, detector, cid):
        for r in self.doc["sensitivity"]["rows"]:
            if r["variant"] == variant and r["detector"] == detector:
                return r["verdicts"].get(cid, "inconclusive")
        if variant == "baseline":
            return self.claim(cid, detector)["verdict"]
        raise InputProblem(f"{self.path}: /sensitivity/rows: no row for {variant} and {detector}")


def detector_table(res):
    dets = res.detectors
    head = "| claim | the seed | " + " | ".join(f"`{d}`, 95% interval | verdict (Holm p)" for d in dets) + " |"
    lines = [head, "|---|---|" + "---|---|" * len(dets)]
    for cid in SEED_CLAIMS:
        cs = [res.claim(cid, d) for d in dets]
        lines.append(f"| `{cid}` | {seed_value(cs[0])} | " + " | ".join(f"{ours(c)} | {verdict(c)}" for c in cs) + " |")
    for cid in PREMISE:
        c = res.claim(cid)
        lines.append(f"| `{cid}` | {c['seed_text'].split(';')[0]} | {ours(c)} | {verdict(c)} |" + " |" * (2 * len(dets) - 2))
    return lines


def checks_line(res):
    parts = []
    for cid in CHECKS:
        vs = " / ".join(res.claim(cid, d)["verdict"] for d in res.detectors)
        parts.append(f"`{cid}` {vs}")
    return "Checks of ours that the seed never states (" + " / ".join(f"`{d}`" for d in res.detectors) + "): " + \
        "; ".join(parts) + "."


def coverage_line(res):
    c = res.claim("cells-match", res.detectors[0])
    f = c["figures"]
    return (f"`cells-match` (`{res.detectors[0]}`): {int(f['outside'])} of {int(f['cells'])} seed values outside our 95% "
            f"prediction intervals; Spearman {f['spearman']:.2f} [{f['spearman_ci95_lo']:.2f}, "
            f"{f['spearman_ci95_hi']:.2f}]; our single-run sd {f['run_sd']:.3f} against the seed's spread "
            f"{f['seed_spread']:.3f}.")


def held_out_line(res):
    differ = []
    for d in res.detectors:
        for cid in SEED_CLAIMS + CHECKS:
            c = res.claim(cid, d)
            h = c.get("held_out")
            if h and h["verdict"] != c["verdict"]:
                differ.append(f"`{cid}` with `{d}` ({c['verdict']} -> {h['verdict']})")
    tail = "every verdict is the same." if not differ else "the verdicts differ for " + ", ".join(differ) + "."
    return "Without the cell pairs that touch a calibration cell: " + tail


def cost_line(res):
    parts = [f"`{cid}` {value(res.claim(cid), res.claim(cid)['observed'])} ({res.claim(cid)['verdict']})" for cid in COST]
    return "Cost, wall-clock on the machine of that run (ratios): " + "; ".join(parts) + "."


def strength_line(res):
    strengths = res.strengths()
    head = ("Verdict per push strength (" + ", ".join(f"{s:g}" for s, _ in strengths) + " N; R reproduced, N not "
            "reproduced, ? inconclusive; " + ", then ".join(f"`{d}`" for d in res.detectors) + "): ")
    parts = []
    for cid in SEED_CLAIMS + CHECKS:
        per_det = ["".join(SHORT[res.row_verdict(v, d, cid)] for _, v in strengths) for d in res.detectors]
        parts.append(f"`{cid}` {' '.join(per_det)}")
    return head + "; ".join(parts) + "."


def paragraph(text, bullet=False):
    return textwrap.wrap(text, width=190, break_long_words=False, break_on_hyphens=False,
                         initial_indent="- " if bullet else "", subsequent_indent="  " if bullet else "")


def block(res, rel_path):
    d = res.doc
    prov = d.get("tecido", {})
    lines = [BEGIN] + paragraph(
        f"Generated by `python3 scripts/readme_tables.py` from [{rel_path}]({rel_path}): `{d['command']}` at commit "
        f"{prov.get('commit', 'unknown')}, {d['seeds']} wind seeds per cell, {d['simulated_time']:g} s per run; "
        "verdicts after Holm's adjustment within each detector's claims (p: the adjusted p of the deciding test).") + [""]
    lines += detector_table(res)
    lines.append("")
    for text in (checks_line(res), coverage_line(res), held_out_line(res), cost_line(res), strength_line(res)):
        lines += paragraph(text, bullet=True)
    lines.append(END)
    return lines


def forced_result(path):
    doc = read_json(path)
    if not isinstance(doc, dict) or doc.get("experiment") != "forced-contact" or "claims" not in doc:
        raise InputProblem(f"{path}: /experiment: not a forced-contact experiment result")
    return doc


def forced_value(claim, x):
    return f"{x:.3f}" if claim["unit"] == "share of runs" else f"{x:+.2f} s"


def forced_block(doc, rel_path):
    prov = doc.get("tecido", {})
    lines = [FORCED_BEGIN] + paragraph(
        f"Generated by `python3 scripts/readme_tables.py` from [{rel_path}]({rel_path}): "
        f"`{prov.get('command_line', doc['command'])}` at commit {prov.get('commit', 'unknown')}, {doc['seeds']} runs "
        f"per response and hold. Multiplicity: {doc['multiplicity']}.") + [""]
    lines += ["| claim | what is measured | ours, 95% interval | verdict |", "|---|---|---|---|"]
    for c in doc["claims"]:
        lo, hi = c["ci95"]
        what = c["unit"] + (f"; {c['observed_text']}" if c.get("observed_text") else "")
        lines.append(f"| `{c['id']}` | {what} | {forced_value(c, c['observed'])} [{forced_value(c, lo)}, "
                     f"{forced_value(c, hi)}] | {c['verdict']}{' (' + c['reason'] + ')' if c.get('reason') else ''} |")
    lines.append(FORCED_END)
    return lines


def bench_goals(path):
    """The bench suite's goal rows of a `tecido suite ... --out` report.json, and its provenance."""
    doc = read_json(path)
    suites = doc.get("suites") if isinstance(doc, dict) else None
    bench = [k for k, x in enumerate(suites or []) if isinstance(x, dict) and x.get("name") == "bench"]
    if not bench:
        raise InputProblem(f"{path}: /suites: no bench suite in this report")
    goals = suites[bench[0]].get("data", {}).get("goals")
    if not isinstance(goals, list) or not goals:
        raise InputProblem(f"{path}: /suites/{bench[0]}/data/goals: missing or empty")
    for k, g in enumerate(goals):
        for key in ("id", "what", "value", "target", "comparison", "unit", "met"):
            if not isinstance(g, dict) or key not in g:
                raise InputProblem(f"{path}: /suites/{bench[0]}/data/goals/{k}: no \"{key}\"")
    return doc, goals


def goal_value(x, unit):
    if x is None:
        return "not measured"
    text = f"{x:.3g}" if abs(x) < 1e4 else f"{x:.0f}"
    return text + (f" {unit}" if unit else "")


def goal_text(g):
    sign = "≥" if g["comparison"] == "at_least" else "≤"
    return f"`{g['id']}` {goal_value(g['value'], g['unit'])} ({sign} {goal_value(g['target'], g['unit'])})"


def speed_block(doc, goals, rel_path):
    prov = doc.get("tecido", {})
    met = [g for g in goals if g["met"] is True]
    missed = [g for g in goals if g["met"] is not True]
    report_md = os.path.join(os.path.dirname(rel_path), "report.md")
    lines = [SPEED_BEGIN] + paragraph(
        f"Generated by `python3 scripts/readme_tables.py` from [{rel_path}]({rel_path}): "
        f"`{prov.get('command_line', 'tecido suite bench')}` at commit {prov.get('commit', 'unknown')}, one run on the "
        f"project's 2-core machine (each ratio within that run; what each goal measures: its report, "
        f"[{report_md}]({report_md}), table Goals): {len(met)} of {len(goals)} speed goals met. Not met (measured, goal): " +
        ("; ".join(goal_text(g) for g in missed) or "none") + f". The other {len(met)} are met.")
    lines.append(SPEED_END)
    return lines


def split_readme(path, text, begin=BEGIN, end=END):
    lines = text.split("\n")
    try:
        b, e = lines.index(begin), lines.index(end)
    except ValueError:
        raise InputProblem(f"{path}: no {begin} ... {end} block")
    if e < b:
        raise InputProblem(f"{path}: the end marker comes before the begin marker")
    return lines[:b], lines[b:e + 1], lines[e + 1:]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    ap.add_argument("--result", default=os.path.join(ROOT, "docs", "results", "self_contact_experiment.json"))
    ap.add_argument("--forced-result", default=os.path.join(ROOT, "docs", "results", "forced_contact", "experiment.json"))
    ap.add_argument("--bench-result", default=os.path.join(ROOT, "docs", "results", "bench", "report.json"))
    ap.add_argument("--check", action="store_true", help="exit 1 when the README's block differs; write nothing")
    a = ap.parse_args(argv)
    try:
        res = Result(a.result)
        try:
            with open(a.readme, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise InputProblem(f"{a.readme}: cannot read: {e.strerror}")
        # Links name the result from the repository's root when it lies inside it (README.md sits
        # there), so that a copy of the README elsewhere gets the same block.
        readme_dir = os.path.dirname(os.path.abspath(a.readme))
        if os.path.abspath(a.result).startswith(ROOT + os.sep):
            readme_dir = ROOT
        before, current, after = split_readme(a.readme, text)
        wanted = block(res, os.path.relpath(os.path.abspath(a.result), readme_dir))
        text = "\n".join(before + wanted + after)
        forced = forced_result(a.forced_result)
        f_before, f_current, f_after = split_readme(a.readme, text, FORCED_BEGIN, FORCED_END)
        f_wanted = forced_block(forced, os.path.relpath(os.path.abspath(a.forced_result), readme_dir))
        text = "\n".join(f_before + f_wanted + f_after)
        bench_doc, goals = bench_goals(a.bench_result)
        s_before, s_current, s_after = split_readme(a.readme, text, SPEED_BEGIN, SPEED_END)
        s_wanted = speed_block(bench_doc, goals, os.path.relpath(os.path.abspath(a.bench_result), readme_dir))
    except InputProblem as e:
        print(f"readme_tables: {e}", file=sys.stderr)
        return 2
    if a.check:
        differ = False
        for name, cur, want, src in (("self-contact", current, wanted, a.result),
                                     ("forced-contact", f_current, f_wanted, a.forced_result),
                                     ("speed-goals", s_current, s_wanted, a.bench_result)):
            if cur != want:
                differ = True
                sys.stderr.writelines(l + "\n" for l in difflib.unified_diff(cur, want, a.readme, src, lineterm=""))
                print(f"readme_tables: {a.readme}: the {name} block differs from {src}; "
                      "run python3 scripts/readme_tables.py", file=sys.stderr)
        return 1 if differ else 0
    out = "\n".join(s_before + s_wanted + s_after)
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(a.readme)), prefix=".README.")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(out)
    os.chmod(tmp, os.stat(a.readme).st_mode & 0o7777)
    os.replace(tmp, a.readme)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
