#!/usr/bin/env python3
"""Turns bench_predicates' JSON output into the RESULTS.md tables.

    bench_predicates --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out=out.json --benchmark_out_format=json
    python3 bench/summarize.py out.json            # the two tables
    python3 bench/summarize.py out.json --targets  # the target verdicts

Uses the median of the repetitions of the `time_per_call` counter (CPU time per predicate
call). Ratios are of medians.
"""
import json
import sys

PREDICATES = ["orient2d", "orient3d", "incircle", "insphere"]
TARGET = {"orient2d": 1.5, "orient3d": 2.0, "incircle": 2.5, "insphere": 2.5}


def load(path):
    with open(path) as f:
        doc = json.load(f)
    med, counters = {}, {}
    for b in doc["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        name = b.get("run_name", b["name"])
        med[name] = b["time_per_call"] * 1e9
        counters[name] = b
    return doc.get("context", {}), med, counters


def fmt(v):
    if v is None:
        return "—"
    if v >= 1000:
        return f"{v / 1000:.2f} µs"
    return f"{v:.2f}"


def ratio(a, b):
    return None if a is None or b is None else a / b


def r(v, limit=None):
    if v is None:
        return "—"
    s = f"{v:.2f}×"
    if limit is not None:
        s += " ✅" if v <= limit else " ❌"
    return s


def targets(med):
    g = lambda p, i, suffix="": med.get(f"BM_{p}_{i}{suffix}")
    ok = lambda b: "**met**" if b else "**not met**"
    for p in PREDICATES:
        n, f, c, pr = g(p, "naive"), g(p, "filtered"), g(p, "cgal"), g(p, "prototype")
        if None in (n, f, c):
            continue
        line = (f"- {p} filtered ≤ {TARGET[p]}× naive: {ok(f / n <= TARGET[p])} "
                f"({f / n:.2f}×); ≤ CGAL Epick: {ok(f <= c)} ({f / c:.2f}×).")
        if pr is not None:
            line += (f" Branch-free prototype: {pr / n:.2f}× naive, {pr / c:.2f}× CGAL.")
        oz = g(p, "prototype_ozaki")
        if oz is not None:
            line += f" Ozaki prototype: {oz / n:.2f}× naive, {oz / c:.2f}× CGAL."
        print(line)
    e, f, c = (g("orient3d", i, "_neardegenerate") for i in ["exact", "filtered", "cgal"])
    if None not in (e, f, c):
        print(f"- near-degenerate orient3d exact ≤ CGAL Epick: {ok(e <= c)} ({e:.0f} ns vs "
              f"{c:.0f} ns, {e / c:.2f}×; filtered {f / c:.2f}×).")


def main():
    ctx, med, cnt = load(sys.argv[1])
    if "--targets" in sys.argv[2:]:
        targets(med)
        return
    g = lambda p, i, suffix="": med.get(f"BM_{p}_{i}{suffix}")
    print(f"Context: {ctx.get('date', '?')}, {ctx.get('num_cpus', '?')} CPUs @ "
          f"{ctx.get('mhz_per_cpu', '?')} MHz, bench_tuples={ctx.get('bench_tuples', '?')}\n")
    print("Uniform random input in [-1,1] (ns per call, median of repetitions)\n")
    print("| predicate | naive | **filtered** | filteronly | exact | CGAL Epick | Shewchuk | "
          "prototype | filtered/naive (target) | filtered/CGAL (≤1) | prototype/naive | "
          "prototype/CGAL |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for p in PREDICATES:
        n, f, fo, e, c, s, pr = (g(p, i) for i in
                                 ["naive", "filtered", "filteronly", "exact", "cgal", "shewchuk",
                                  "prototype"])
        extra = ""
        oz = g(p, "prototype_ozaki")
        if oz is not None:
            extra = f" (ozaki: {fmt(oz)}, {r(ratio(oz, n))} naive, {r(ratio(oz, c))} CGAL)"
        print(f"| {p} | {fmt(n)} | **{fmt(f)}** | {fmt(fo)} | {fmt(e)} | {fmt(c)} | {fmt(s)} | "
              f"{fmt(pr)}{extra} | {r(ratio(f, n), TARGET[p])} (≤{TARGET[p]}) | "
              f"{r(ratio(f, c), 1.0)} | {r(ratio(pr, n), TARGET[p])} | {r(ratio(pr, c), 1.0)} |")
    print("\nNear-degenerate input (ns per call, median of repetitions)\n")
    print("| predicate | naive wrong sign | filter uncertain | naive | **filtered** | exact | "
          "CGAL Epick | Shewchuk | prototype | exact/CGAL | filtered/CGAL | Shewchuk/CGAL |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    sfx = "_neardegenerate"
    for p in PREDICATES:
        n, f, e, c, s, pr = (g(p, i, sfx) for i in
                             ["naive", "filtered", "exact", "cgal", "shewchuk", "prototype"])
        wrong = cnt.get(f"BM_{p}_naive{sfx}", {}).get("wrong_sign_frac")
        unc = cnt.get(f"BM_{p}_filtered{sfx}", {}).get("uncertain_frac")
        pct = lambda v: "—" if v is None else f"{100 * v:.1f} %"
        lim = 1.0 if p == "orient3d" else None
        extra = ""
        oz, fe = g(p, "prototype_ozaki", sfx), g(p, "prototype_fastexact", sfx)
        if oz is not None:
            extra = f" (ozaki: {fmt(oz)}; fastexact: {fmt(fe)})"
        print(f"| {p} | {pct(wrong)} | {pct(unc)} | {fmt(n)} | **{fmt(f)}** | {fmt(e)} | "
              f"{fmt(c)} | {fmt(s)} | {fmt(pr)}{extra} | {r(ratio(e, c), lim)} | {r(ratio(f, c))} | "
              f"{r(ratio(s, c))} |")


if __name__ == "__main__":
    main()
