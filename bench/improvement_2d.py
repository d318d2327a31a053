#!/usr/bin/python3
"""The improvement stage's time (issue 12, items 11 and 13), two certimesh binaries side by side
in the same run: each case meshed with and without --no-improve; the stage times are the ones
`certimesh mesh` prints, the CPU time is the process's user time (the machine is shared).

  /usr/bin/python3 bench/improvement_2d.py --new build/bin/certimesh --old OLD/certimesh
      [--timeout 300] [--repetitions 1]
"""
import argparse
import os
import re
import resource
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import graded_domains  # noqa: E402

CASES = [
    # name, domain, options (both binaries)
    ("unit square h=0.005, delaunay", "builtin:square", ["--size", "0.005", "--algorithm", "delaunay"]),
    ("unit square h=0.005, front", "builtin:square", ["--size", "0.005"]),
    ("wavy 10^4-gon, boundary step (growth 1)", "wavy-10000.poly", ["--grading", "0"]),
    ("wavy 10^4-gon, default size", "wavy-10000.poly", []),
]


def run(binary, args, timeout):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    start = time.perf_counter()
    try:
        r = subprocess.run([binary] + args, capture_output=True, text=True, timeout=timeout)
        out = r.stdout + r.stderr
    except subprocess.TimeoutExpired:
        return None
    wall = time.perf_counter() - start
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    stage = re.search(r"improvement ([0-9.]+)\)", out)
    tri = re.search(r"([0-9]+) triangles\n", out)
    worst = re.search(r"worst ([0-9.]+)", out)
    return {"wall": wall, "cpu": cpu, "improvement": float(stage.group(1)) if stage else 0.0,
            "triangles": int(tri.group(1)) if tri else 0, "worst": float(worst.group(1)) if worst else 0.0}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--new", required=True)
    ap.add_argument("--old", required=True)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--out", default="build/improvement_2d")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    loops, holes = graded_domains.domains()["wavy-10000"]
    graded_domains.write_poly(os.path.join(args.out, "wavy-10000.poly"), loops, holes)
    print("| case | binary | triangles | worst | improvement stage s | run CPU s | run CPU s, --no-improve |")
    print("|---|---|---|---|---|---|---|")
    for name, domain, options in CASES:
        path = domain if domain.startswith("builtin:") else os.path.join(args.out, domain)
        for label, binary in (("old", args.old), ("new", args.new)):
            opts = options if label == "new" else [o for o in options if o not in ("--grading", "0")]
            if label == "old" and not options and domain.endswith(".poly"):
                continue  # the old binary has no boundary-adapted size
            common = ["mesh", path, "-o", os.path.join(args.out, "m.msh"), "--quiet"] + opts
            with_improve = run(binary, common, args.timeout)
            without = run(binary, common + ["--no-improve"], args.timeout)
            if with_improve is None:
                print(f"| {name} | {label} | timed out after {args.timeout:.0f} s | | | | "
                      f"{without['cpu']:.2f} |" if without else f"| {name} | {label} | timed out | | | | |")
                continue
            print(f"| {name} | {label} | {with_improve['triangles']} | {with_improve['worst']:.3f} | "
                  f"{with_improve['improvement']:.2f} | {with_improve['cpu']:.2f} | "
                  f"{without['cpu'] if without else float('nan'):.2f} |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
