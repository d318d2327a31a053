#!/usr/bin/python3
"""Tests of `certimesh predicates` (the streaming batch interface) against an independent
exact oracle: Python's correctly rounded float parsing (float(), float.fromhex) and exact
rational determinants (fractions.Fraction holds every double exactly).

usage:
  cli_batch_test.py oracle <certimesh> [lines]     answers, errors and exit status, 3 modes
  cli_batch_test.py memory <certimesh> [lines]     constant memory: max RSS via /usr/bin/time -v
  cli_batch_test.py usage <certimesh>              --help, --version, demo, bad subcommands

Deterministic: a fixed seed; no time-based randomness.
"""
import math
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction

SEED = 20261129

# --------------------------------------------------------------------------------------
# The oracle
# --------------------------------------------------------------------------------------


def parse(token):
    """Exact value of a token as certimesh must read it (correctly rounded)."""
    t = token.lower().lstrip("+-")
    if t.startswith("0x"):
        return float.fromhex(token)
    return float(token)


def det(m):
    n = len(m)
    if n == 1:
        return m[0][0]
    if n == 2:
        return m[0][0] * m[1][1] - m[0][1] * m[1][0]
    total = 0
    for j in range(n):
        if m[0][j] == 0:
            continue
        minor = [row[:j] + row[j + 1:] for row in m[1:]]
        term = m[0][j] * det(minor)
        total += term if j % 2 == 0 else -term
    return total


def sign(x):
    return (x > 0) - (x < 0)


def points(values, dim):
    return [tuple(Fraction(v) for v in values[i:i + dim]) for i in range(0, len(values), dim)]


def diff(p, q):
    return [a - b for a, b in zip(p, q)]


def lifted(p, q):
    d = diff(p, q)
    return d + [sum(x * x for x in d)]


# Conventions (docs/design README, decision 4; predicate headers):
#   orient2d(a,b,c) = sign det[a-c; b-c];  orient3d(a,b,c,d) = sign det[a-d; b-d; c-d];
#   incircle(a,b,c,d) = sign det[a-d, |a-d|^2; ...] (> 0: d inside the circle of ccw a,b,c);
#   insphere(a,b,c,d,e) = sign det[a-e, |a-e|^2; ...] (> 0: e inside when orient3d(a,b,c,d) > 0).
def oracle_sign(command, values):
    if command == "orient2d":
        a, b, c = points(values, 2)
        return sign(det([diff(a, c), diff(b, c)]))
    if command == "orient3d":
        a, b, c, d = points(values, 3)
        return sign(det([diff(a, d), diff(b, d), diff(c, d)]))
    if command == "incircle":
        a, b, c, d = points(values, 2)
        return sign(det([lifted(a, d), lifted(b, d), lifted(c, d)]))
    if command == "insphere":
        a, b, c, d, e = points(values, 3)
        return sign(det([lifted(a, e), lifted(b, e), lifted(c, e), lifted(d, e)]))
    raise ValueError(command)


# Independent exact intersection oracle: two elements (convex hulls of their points)
# intersect beyond their shared vertices S (same coordinates, bit for bit, in both) when
# some point x = sum l_i a_i = sum m_j b_j (l, m >= 0, sum l = sum m = 1) lies outside
# conv(S). When A's points are affinely independent, conv(S) is the face of A where the
# weights of A's other vertices vanish, so the test is: max sum_{i not in S} l_i > 0, an
# exact linear program (rational simplex, Bland's rule).
def simplex_max(A, b, c):
    """max c.x subject to A x = b, x >= 0 (exact). None when infeasible; the problems here
    are bounded."""
    m, n = len(A), len(A[0])
    T = []
    for i in range(m):
        row, rhs = [Fraction(v) for v in A[i]], Fraction(b[i])
        if rhs < 0:
            row, rhs = [-v for v in row], -rhs
        T.append(row + [Fraction(int(k == i)) for k in range(m)] + [rhs])
    basis = [n + i for i in range(m)]

    def run(cost, allowed):
        while True:
            entering = None
            for j in range(allowed):
                if j in basis:
                    continue
                reduced = cost[j] - sum(cost[basis[i]] * T[i][j] for i in range(m))
                if reduced > 0:
                    entering = j
                    break
            if entering is None:
                return
            best = None
            for i in range(m):
                if T[i][entering] > 0:
                    ratio = T[i][-1] / T[i][entering]
                    if best is None or ratio < best[0] or (ratio == best[0] and basis[i] < basis[best[1]]):
                        best = (ratio, i)
            if best is None:
                raise ValueError("unbounded")
            r = best[1]
            pivot = T[r][entering]
            T[r] = [v / pivot for v in T[r]]
            for i in range(m):
                if i != r and T[i][entering] != 0:
                    f = T[i][entering]
                    T[i] = [v - f * w for v, w in zip(T[i], T[r])]
            basis[r] = entering

    # Phase 1: maximize -(sum of artificials).
    run([Fraction(0)] * n + [Fraction(-1)] * m, n + m)
    if any(basis[i] >= n and T[i][-1] != 0 for i in range(m)):
        return None
    # Drive zero artificials out of the basis where possible, then phase 2 on originals.
    for i in range(m):
        if basis[i] >= n:
            for j in range(n):
                if j not in basis and T[i][j] != 0:
                    pivot = T[i][j]
                    T[i] = [v / pivot for v in T[i]]
                    for k in range(m):
                        if k != i and T[k][j] != 0:
                            f = T[k][j]
                            T[k] = [v - f * w for v, w in zip(T[k], T[i])]
                    basis[i] = j
                    break
    cost = [Fraction(v) for v in c] + [Fraction(0)] * m
    run(cost, n)
    return sum(cost[basis[i]] * T[i][-1] for i in range(m))


def affinely_independent(pts):
    rows = [diff(p, pts[0]) for p in pts[1:]]
    rank, rows = 0, [r[:] for r in rows]
    cols = len(pts[0])
    for col in range(cols):
        piv = next((i for i in range(rank, len(rows)) if rows[i][col] != 0), None)
        if piv is None:
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        for i in range(len(rows)):
            if i != rank and rows[i][col] != 0:
                f = rows[i][col] / rows[rank][col]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[rank])]
        rank += 1
    return rank == len(pts) - 1


def hulls_intersect_beyond_shared(a_raw, b_raw, dim):
    """a_raw, b_raw: lists of float tuples. True/False, or None when both are degenerate."""
    def key(p):
        return tuple(v.hex() for v in p)
    A = [tuple(Fraction(v) for v in p) for p in a_raw]
    B = [tuple(Fraction(v) for v in p) for p in b_raw]
    shared = set(map(key, a_raw)) & set(map(key, b_raw))
    if affinely_independent(A):
        first, first_raw, second = A, a_raw, B
    elif affinely_independent(B):
        first, first_raw, second = B, b_raw, A
    else:
        if shared:
            return None
        first, first_raw, second = A, a_raw, B  # no shared vertices: plain closed hulls
    na, nb = len(first), len(second)
    rows = [[Fraction(1)] * na + [Fraction(0)] * nb, [Fraction(0)] * na + [Fraction(1)] * nb]
    for k in range(dim):
        rows.append([p[k] for p in first] + [-q[k] for q in second])
    rhs = [1, 1] + [0] * dim
    if not shared:
        return simplex_max(rows, rhs, [0] * (na + nb)) is not None
    objective = [0 if key(p) in shared else 1 for p in first_raw] + [0] * nb
    best = simplex_max(rows, rhs, objective)
    return best is not None and best > 0


def oracle_intersection(command, values):
    npoints, dim = INTERSECTIONS[command]
    first = {"seg_seg2d": 2, "tri_seg2d": 3, "tri_seg3d": 3, "tet_tri": 4, "tri_tri3d": 3}[command]
    pts = [tuple(values[i:i + dim]) for i in range(0, len(values), dim)]
    return hulls_intersect_beyond_shared(pts[:first], pts[first:], dim)


PREDICATES = {"orient2d": (3, 2), "orient3d": (4, 3), "incircle": (4, 2), "insphere": (5, 3)}
INTERSECTIONS = {"seg_seg2d": (4, 2), "tri_seg2d": (5, 2), "tri_seg3d": (5, 3),
                 "tet_tri": (7, 3), "tri_tri3d": (6, 3)}

# --------------------------------------------------------------------------------------
# Input generation
# --------------------------------------------------------------------------------------


def ulps(x, k):
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


def fmt(rng, x):
    """A random exact-enough spelling of x, or a string whose correctly rounded value is x."""
    r = rng.random()
    if r < 0.30:
        return repr(x)
    if r < 0.50:
        return x.hex()
    if r < 0.60:
        return x.hex().upper().replace("0X", "0x") if rng.random() < 0.5 else x.hex().upper()
    if r < 0.70:
        return "%.17g" % x
    if r < 0.80:
        return "%.40e" % x  # more digits than needed: still rounds to x
    if r < 0.85 and math.copysign(1.0, x) > 0:
        return "+" + repr(x)
    if r < 0.90 and x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def random_decimal(rng):
    """A long decimal literal: its correctly rounded double is what both sides must agree on."""
    digits = "".join(rng.choice("0123456789") for _ in range(rng.randint(18, 30)))
    return "%s0.%se%d" % (rng.choice(["", "-"]), digits, rng.randint(-30, 30))


def coordinate(rng):
    kind = rng.random()
    if kind < 0.25:
        return float(rng.randint(-3, 3))
    if kind < 0.35:
        return rng.choice([0.5, 12.0, 24.0, 0.1, 0.2, 0.3, 1e-300, 5e-324, 1e150, -1e150, -0.0])
    if kind < 0.45:
        return rng.uniform(-1, 1) * 2.0 ** rng.randint(-1074, 1000) if rng.random() < 0.3 else \
            rng.uniform(-1, 1) * 2.0 ** rng.randint(-60, 60)
    return rng.uniform(-10, 10)


def near_degenerate(rng, npoints, dim):
    """Points near a line (2D) or plane (3D), or near a common circle/sphere: the hard cases."""
    if dim == 2:
        a = [rng.uniform(-5, 5), rng.uniform(-5, 5)]
        b = [rng.uniform(-5, 5), rng.uniform(-5, 5)]
        pts = []
        for i in range(npoints):
            t = rng.choice([0.0, 1.0, 0.5, 2.0, -1.0, 0.25, rng.uniform(-2, 2)])
            p = [a[k] + t * (b[k] - a[k]) for k in range(2)]
            if rng.random() < 0.5:
                p = [ulps(v, rng.randint(-3, 3)) for v in p]
            pts.append(p)
        if rng.random() < 0.3:  # Kettner grid style
            pts = [[ulps(0.5, rng.randint(0, 255)), ulps(0.5, rng.randint(0, 255))], [12.0, 12.0],
                   [24.0, 24.0]] + [[rng.choice([0.5, 12.0, 24.0])] * 2 for _ in range(npoints - 3)]
        return [v for p in pts for v in p]
    a = [rng.uniform(-5, 5) for _ in range(3)]
    u = [rng.uniform(-5, 5) for _ in range(3)]
    w = [rng.uniform(-5, 5) for _ in range(3)]
    pts = []
    for i in range(npoints):
        s, t = rng.choice([0.0, 1.0, 0.5, -1.0, rng.uniform(-2, 2)]), rng.choice([0.0, 1.0, 0.5, 2.0])
        p = [a[k] + s * u[k] + t * w[k] for k in range(3)]
        if rng.random() < 0.5:
            p = [ulps(v, rng.randint(-2, 2)) for v in p]
        pts.append(p)
    return [v for p in pts for v in p]


def cocircular(rng, npoints, dim):
    """Integer points on a circle/sphere (x^2+y^2 = 25 / 25 + small), exactly degenerate."""
    circle = [(5, 0), (0, 5), (-5, 0), (0, -5), (3, 4), (4, 3), (-3, 4), (3, -4), (-4, -3)]
    sphere = [(5, 0, 0), (0, 5, 0), (0, 0, 5), (-5, 0, 0), (0, -5, 0), (3, 4, 0), (0, 3, 4),
              (4, 0, 3), (0, 0, -5), (-3, 0, -4)]
    base = circle if dim == 2 else sphere
    pts = rng.sample(base, npoints)
    if rng.random() < 0.5:
        j = rng.randrange(npoints)
        pts[j] = tuple(ulps(float(v), rng.randint(-1, 1)) for v in pts[j])
    scale = 2.0 ** rng.randint(-20, 20)
    return [float(v) * scale for p in pts for v in p]


def intersection_values(rng, command):
    npoints, dim = INTERSECTIONS[command]
    first = {"seg_seg2d": 2, "tri_seg2d": 3, "tri_seg3d": 3, "tet_tri": 4, "tri_tri3d": 3}[command]
    r = rng.random()
    if r < 0.45:  # small integers: touching, overlapping and collinear/coplanar contacts
        pts = [[float(rng.randint(-2, 2)) for _ in range(dim)] for _ in range(npoints)]
    elif r < 0.65:
        vals = near_degenerate(rng, npoints, dim)
        pts = [vals[i:i + dim] for i in range(0, len(vals), dim)]
    else:
        scale = 2.0 ** rng.randint(-40, 40)
        pts = [[rng.uniform(-1, 1) * scale for _ in range(dim)] for _ in range(npoints)]
    if rng.random() < 0.35:  # share one or two vertices between the elements
        for _ in range(rng.randint(1, 2)):
            i, j = rng.randrange(first), rng.randrange(first, npoints)
            pts[j] = list(pts[i])
    if rng.random() < 0.15:  # nudge one point by an ulp
        p = rng.choice(pts)
        k = rng.randrange(dim)
        p[k] = ulps(p[k], rng.choice([-1, 1]))
    return [v for p in pts for v in p]


def valid_values(rng, command):
    npoints, dim = {**PREDICATES, **INTERSECTIONS}[command]
    if command in INTERSECTIONS:
        return intersection_values(rng, command)
    r = rng.random()
    if r < 0.35:
        return near_degenerate(rng, npoints, dim)
    if r < 0.50 and command in ("incircle", "insphere"):
        return cocircular(rng, npoints, dim)
    if r < 0.60:  # a repeated point
        vals = [coordinate(rng) for _ in range(npoints * dim)]
        i, j = rng.sample(range(npoints), 2)
        vals[j * dim:(j + 1) * dim] = vals[i * dim:(i + 1) * dim]
        return vals
    return [coordinate(rng) for _ in range(npoints * dim)]


BAD_TOKENS = [("nan", "NaN"), ("-nan", "NaN"), ("NaN", "NaN"), ("nan(0x8)", "NaN"),
              ("inf", "infinity"), ("-Infinity", "infinity"), ("INF", "infinity"),
              ("1e400", "out of range"), ("-1e400", "out of range"), ("0x1p1024", "out of range"),
              ("1.2.3", "malformed"), ("0x", "malformed"), ("abc", "malformed"), ("1e", "malformed"),
              ("--1", "malformed"), ("1,5", "malformed"), ("0x1.8q3", "malformed"), ("1.0f", "malformed")]


def generate(rng, count, commands):
    """Returns (lines, expected) where expected[i] is None (no output), ('ok', cmd, values,
    points dim) or ('error', fragment)."""
    lines, expected = [], []
    for _ in range(count):
        r = rng.random()
        if r < 0.03:
            lines.append(rng.choice(["", "   ", "\t", "# a comment", "   # indented comment"]))
            expected.append(None)
            continue
        command = rng.choice(commands)
        npoints, dim = {**PREDICATES, **INTERSECTIONS}[command]
        values = valid_values(rng, command)
        tokens = [fmt(rng, v) for v in values]
        if rng.random() < 0.05:  # long decimals: correct rounding must agree with Python's
            for k in range(len(tokens)):
                if rng.random() < 0.5:
                    tokens[k] = random_decimal(rng)
                    values[k] = float(tokens[k])
        if r < 0.10:
            bad, why = rng.choice(BAD_TOKENS)
            k = rng.randrange(len(tokens))
            tokens[k] = bad
            expected.append(("error", why))
        elif r < 0.12:
            tokens = tokens[:-1] if rng.random() < 0.5 else tokens + ["1"]
            expected.append(("error", "expects"))
        elif r < 0.13:
            command = rng.choice(["orient4d", "ORIENT2D", "incircle3d", "0"])
            expected.append(("error", "unknown command"))
        else:
            expected.append(("ok", command, values))
        sep = rng.choice([" ", " ", "  ", "\t"])
        line = command + sep + sep.join(tokens)
        if rng.random() < 0.03:
            line += "   # trailing comment"
        if rng.random() < 0.02:
            line = "  " + line + " \r"
        lines.append(line)
    return lines, expected


# --------------------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------------------

failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        if len(failures) <= 20:
            print("FAIL:", message)


def run(certimesh, args, text):
    p = subprocess.run([certimesh] + args, input=text.encode(), stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, check=False)
    return p.returncode, p.stdout.decode().splitlines(), p.stderr.decode().splitlines()


def intersection_available(certimesh):
    rc, out, err = run(certimesh, ["predicates"], "seg_seg2d 0 0 1 1 0 1 1 0\n")
    return rc == 0 and out == ["intersect"]


def distinct_points(values, dim):
    pts = [tuple(values[i:i + dim]) for i in range(0, len(values), dim)]
    return len(set(pts)) == len(pts)


def test_oracle(certimesh, count):
    rng = random.Random(SEED)
    commands = list(PREDICATES)
    have_intersection = intersection_available(certimesh)
    if have_intersection:
        commands += list(INTERSECTIONS)
    else:
        print("note: intersection commands not available in this build; predicates only")
    lines, expected = generate(rng, count, commands)
    text = "\n".join(lines) + "\n"
    want_errors = {i + 1: e[1] for i, e in enumerate(expected) if e and e[0] == "error"}
    answered = [e for e in expected if e and e[0] == "ok"]
    print("%d lines: %d queries, %d malformed, %d blank/comment" %
          (len(lines), len(answered), len(want_errors), expected.count(None)))

    results = {}
    for mode in ("exact", "filter", "sos"):
        rc, out, err = run(certimesh, ["predicates", "--mode", mode], text)
        check(rc == (1 if want_errors else 0), "%s: exit status %d" % (mode, rc))
        got_errors = {}
        for e in err:
            check(e.startswith("error: line "), "%s: stderr line %r" % (mode, e))
            try:
                n = int(e[len("error: line "):].split(":", 1)[0])
                got_errors[n] = e
            except ValueError:
                check(False, "%s: unparsable stderr line %r" % (mode, e))
        check(sorted(got_errors) == sorted(want_errors),
              "%s: error lines differ: extra %s missing %s" % (
                  mode, sorted(set(got_errors) - set(want_errors))[:10],
                  sorted(set(want_errors) - set(got_errors))[:10]))
        for n, why in want_errors.items():
            if n in got_errors:
                check(why.lower() in got_errors[n].lower(),
                      "%s: line %d: message %r lacks %r" % (mode, n, got_errors[n], why))
        check(len(out) == len(answered), "%s: %d answers for %d queries" % (mode, len(out), len(answered)))
        results[mode] = out

    exact_zero = filter_uncertain = intersect_checked = 0
    for k, e in enumerate(answered):
        if k >= min(len(results["exact"]), len(results["filter"]), len(results["sos"])):
            break
        _, command, values = e
        ex, fi, so = results["exact"][k], results["filter"][k], results["sos"][k]
        npoints, dim = {**PREDICATES, **INTERSECTIONS}[command]
        where = "query %d (%s %s)" % (k + 1, command, " ".join(repr(v) for v in values))
        if command in PREDICATES:
            want = oracle_sign(command, values)
            exact_zero += want == 0
            check(ex == str(want), "exact %s: got %s want %d" % (where, ex, want))
            filter_uncertain += fi == "?"
            check(fi in ("?", str(want)) and fi != "0", "filter %s: got %s exact %d" % (where, fi, want))
            if want != 0:
                check(so == str(want), "sos %s: got %s exact %d" % (where, so, want))
            else:
                check(so in ("-1", "1") or not distinct_points(values, dim),
                      "sos %s: zero for distinct points" % where)
        else:
            check(ex in ("intersect", "disjoint"), "exact %s: got %r" % (where, ex))
            check(so == ex, "sos %s: %s differs from exact %s" % (where, so, ex))
            # conservative: may err only towards "intersect" (second-type errors forbidden)
            check(not (fi == "disjoint" and ex == "intersect"),
                  "filter %s: disjoint but exactly intersecting" % where)
            if True:
                want = oracle_intersection(command, values)
                if want is not None:
                    intersect_checked += 1
                    check(ex == ("intersect" if want else "disjoint"),
                          "exact %s: got %s want %s" % (where, ex, want))
    print("oracle: %d exact zeros, %d filter-uncertain, %d intersection answers checked "
          "independently" % (exact_zero, filter_uncertain, intersect_checked))
    check(exact_zero >= len(answered) // 20, "too few exact zeros (%d): generator lost its bite" % exact_zero)

    # A clean input exits 0; a line with errors only still exits 1 with no stdout.
    rc, out, err = run(certimesh, ["predicates"], "# only comments\n\norient2d 0 0 1 0 0 1\n")
    check(rc == 0 and out == ["1"] and err == [], "clean input: rc %d out %r err %r" % (rc, out, err))
    rc, out, err = run(certimesh, ["predicates"], "orient2d nan 0 1 0 0 1\n")
    check(rc == 1 and out == [] and len(err) == 1 and err[0].startswith("error: line 1: "),
          "nan line: rc %d out %r err %r" % (rc, out, err))
    rc, out, err = run(certimesh, ["predicates", "--mode", "bogus"], "")
    check(rc == 2 and err and err[0].startswith("error: "), "bad mode: rc %d err %r" % (rc, err))


def test_usage(certimesh):
    rc, out, err = run(certimesh, ["--help"], "")
    check(rc == 0 and any("predicates" in l for l in out), "--help: rc %d" % rc)
    rc, out, err = run(certimesh, ["--version"], "")
    check(rc == 0 and len(out) == 1 and out[0].startswith("certimesh "), "--version: %r" % out)
    rc, out, err = run(certimesh, ["frobnicate"], "")
    check(rc != 0 and err and err[0].startswith("error: "), "unknown subcommand: rc %d err %r" % (rc, err))
    rc, out, err = run(certimesh, [], "")
    check(rc != 0, "no subcommand: rc %d" % rc)
    rc, out, err = run(certimesh, ["demo"], "")
    check(rc == 0 and out and "0 of 65536" in "\n".join(out) and "agree" in out[-1],
          "demo: rc %d, last line %r" % (rc, out[-1:] if out else None))


def max_rss_kb(certimesh, block, repeats, expected_block):
    with tempfile.TemporaryDirectory() as tmp:
        out_path, err_path = os.path.join(tmp, "out"), os.path.join(tmp, "err")
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            p = subprocess.Popen(["/usr/bin/time", "-v", certimesh, "predicates"],
                                 stdin=subprocess.PIPE, stdout=out, stderr=err)
            data = block.encode()
            for _ in range(repeats):
                p.stdin.write(data)
            p.stdin.close()
            rc = p.wait()
        check(rc == 0, "memory run: exit status %d" % rc)
        rss = None
        with open(err_path) as f:
            for line in f:
                if "Maximum resident set size" in line:
                    rss = int(line.rsplit(":", 1)[1])
                elif "Elapsed (wall clock)" in line:
                    elapsed = line.rsplit(": ", 1)[1].strip()
        with open(out_path) as f:
            answers = f.read().split("\n")[:-1]
        check(len(answers) == len(expected_block) * repeats,
              "memory run: %d answers, want %d" % (len(answers), len(expected_block) * repeats))
        check(answers == expected_block * repeats, "memory run: answers differ from the oracle")
        return rss, elapsed


def test_memory(certimesh, count):
    # A block of 1000 queries, repeated: 1 in 10 from the hard generator (exact stages,
    # GMP fallbacks), the rest plain random coordinates (the filter decides them).
    rng = random.Random(SEED + 1)
    lines, expected = generate(rng, 1000, list(PREDICATES))
    hard = [(l, e) for l, e in zip(lines, expected) if e and e[0] == "ok"][:100]
    pairs = []
    for i in range(1000):
        if i % 10 == 0:
            pairs.append(hard[i // 10])
            continue
        command = rng.choice(list(PREDICATES))
        npoints, dim = PREDICATES[command]
        values = [rng.uniform(-100, 100) for _ in range(npoints * dim)]
        pairs.append((command + " " + " ".join(fmt(rng, v) for v in values), ("ok", command, values)))
    block = "".join(l + "\n" for l, _ in pairs)
    want = [str(oracle_sign(e[1], e[2])) for _, e in pairs]
    small_rss, _ = max_rss_kb(certimesh, block, 10, want)
    repeats = max(1, count // len(pairs))
    big_rss, elapsed = max_rss_kb(certimesh, block, repeats, want)
    print("max RSS: %d kB for %d lines, %d kB for %d lines (wall %s)" %
          (small_rss, 10 * len(pairs), big_rss, repeats * len(pairs), elapsed))
    check(big_rss <= small_rss + 1024, "RSS grew with the input: %d kB -> %d kB" % (small_rss, big_rss))
    check(big_rss < 16 * 1024, "max RSS %d kB is not small" % big_rss)


def main():
    what, certimesh = sys.argv[1], sys.argv[2]
    count = int(sys.argv[3]) if len(sys.argv) > 3 else None
    if what == "oracle":
        test_oracle(certimesh, count or 4000)
    elif what == "memory":
        test_memory(certimesh, count or 2000000)
    elif what == "usage":
        test_usage(certimesh)
    else:
        sys.exit("unknown test " + what)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
