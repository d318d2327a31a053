#!/usr/bin/env python3
"""Regenerate the Gappa scripts proofs/gappa/*.g from the evaluation order of
predicates/include/certimesh/predicates/detail/filters.h.

Maintenance tool, not part of the test suite: the tests read the .g files only.
Each script is emitted twice: first with `in ?` goals, so that Gappa reports the tightest
enclosures it can prove; then with those enclosures rounded up to binary64 (the error
bound) or to a power of two (the ranges) as the goals that `gappa` must prove.

Model (proofs/README.md, section 2): every quantity is divided by the product of the
maxima of its degree, so a rounded difference is T*(1+d) with |T| <= 1+2^-53, an
addition is (a+b)*(1+d), a product is a*b*(1+d) + eta, |d| <= 2^-53 and
|eta| <= 2^-1074 / lower_guard^degree (underflow of a product; additions and
differences of binary64 numbers are exact when they underflow).

Usage: python3 generate.py [--dry-run] [name ...]     (run from any directory)
"""
import os
import re
import subprocess
import sys
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
U = "0x1p-53"
T_MAX = "0x1.00000000000008p0"  # 1 + 2^-53


def hexf(q):
    """Exact hex literal of a dyadic rational (as Python's float.hex when it fits)."""
    q = Fraction(q)
    assert q > 0
    m, e = q.numerator, 0
    d = q.denominator
    while d > 1:
        assert d % 2 == 0
        d //= 2
        e -= 1
    while m % 2 == 0:
        m //= 2
        e += 1
    nb = m.bit_length()
    frac = m - (1 << (nb - 1))
    fb = nb - 1
    digits = (fb + 3) // 4
    frac <<= digits * 4 - fb
    exp = e + nb - 1
    s = f"0x1.{frac:0{digits}x}p{exp:+d}" if digits else f"0x1p{exp:+d}"
    return s


def round_up_double(q):
    q = Fraction(q)
    e = 0
    while q >= 2 ** (e + 1):
        e += 1
    while q < 2 ** e:
        e -= 1
    ulp = Fraction(2) ** (e - 52)
    n = -(-q // ulp)
    return n * ulp


def pow2_above(q):
    e = 0
    while Fraction(2) ** e < q:
        e += 1
    while e > 0 and Fraction(2) ** (e - 1) >= q:
        e -= 1
    return Fraction(2) ** e


class Script:
    """One Gappa script in the relative (normalized) model."""

    def __init__(self, name, lower_exp, header):
        self.name = name
        self.l = -lower_exp  # lower guard = 2^-l
        self.header = header
        self.defs = []
        self.hyps = []
        self.hints = []
        self.deg = {}
        self.order = []
        self.goals = []  # (expr, kind, tag) kind in E, range, export
        self.ops = 0
        self.exact = set()  # doubles known exactly (stage 2: rounded differences, tails)
        self.capmap = {}  # exact counterpart names other than the capitalized one

    def cap(self, n):
        if n in self.exact:
            return n
        return self.capmap.get(n, n[0].upper() + n[1:])

    def comment(self, text):
        self.defs.append("")
        self.defs.append("# " + text)

    def diff(self, n, axis_max):
        N = self.cap(n)
        self.defs.append(f"{n} = {N} * (1 + d_{n});   # fl(difference) / {axis_max}")
        self.hyps.append((f"|{N}| <= {T_MAX}", "@diff"))
        self.hyps.append((f"|d_{n}| <= {U}", "@delta"))
        self.hints.append(f"{n} - {N} -> {N} * d_{n};")
        self.deg[n] = 1
        self.order.append(n)

    def rounded_diff(self, n, axis_max):
        """A rounded difference, an input known exactly: |n| <= 1 after normalization."""
        self.hyps.append((f"|{n}| <= 1", "@rounded_diff"))
        self.deg[n] = 1
        self.exact.add(n)

    def tail(self, n, h, axis_max):
        """The exact tail of the rounded difference h (two_diff): |tail| <= 2^-53 |h|."""
        self.defs.append(f"{n} = {h} * e_{n};   # tail of {h}, / {axis_max}")
        self.hyps.append((f"|e_{n}| <= {U}", "@tail"))
        self.deg[n] = 1
        self.exact.add(n)
        self.order.append(n)

    def imported(self, n, deg, err, rng, exact_rng, src):
        N = self.cap(n)
        self.hyps.append((f"|{n} - {N}| <= {err}", f"@import {src}:{n}.err"))
        self.hyps.append((f"|{n}| <= {rng}", f"@import {src}:{n}.range"))
        self.hyps.append((f"|{N}| <= {exact_rng}", f"@import {src}:{N}.range"))
        self.deg[n] = deg

    def mul(self, n, a, b):
        N, A, B = self.cap(n), self.cap(a), self.cap(b)
        k = self.deg[a] + self.deg[b]
        self.defs.append(f"{n} = {a} * {b} * (1 + d_{n}) + eta_{n};  {N} = {A} * {B};")
        self.hyps.append((f"|d_{n}| <= {U}", "@delta"))
        self.hyps.append((f"|eta_{n}| <= 0x1p{-1074 + k * self.l}", f"@eta degree={k}"))
        terms = [t for t, ex in ((f"({a} - {A}) * {b}", a in self.exact),
                                 (f"{A} * ({b} - {B})", b in self.exact)) if not ex]
        own = f"{a} * {b} * d_{n} + eta_{n}"
        self.hints.append(f"{n} - {N} -> " + (f"({' + '.join(terms)}) + " if terms else "") + own + ";")
        self.deg[n] = k
        self.order.append(n)

    def add(self, n, a, b, op="+"):
        N, A, B = self.cap(n), self.cap(a), self.cap(b)
        assert self.deg[a] == self.deg[b], (a, b)
        self.defs.append(f"{n} = ({a} {op} {b}) * (1 + d_{n});  {N} = {A} {op} {B};")
        self.hyps.append((f"|d_{n}| <= {U}", "@delta"))
        if a in self.exact or b in self.exact:
            # an operand known exactly (an error-free tail) contributes no error term
            terms = [t for t, ex in ((f"({a} - {A})", a in self.exact),
                                     (f"{op} ({b} - {B})", b in self.exact)) if not ex]
            first = " ".join(terms).lstrip("+ ")
            if first.startswith("- "):
                first = "-" + first[2:]
            lead = f"({first}) + " if terms else ""
            self.hints.append(f"{n} - {N} -> {lead}({a} {op} {b}) * d_{n};")
        else:
            self.hints.append(f"{n} - {N} -> (({a} - {A}) {op} ({b} - {B})) + ({a} {op} {b}) * d_{n};")
        self.deg[n] = self.deg[a]
        self.order.append(n)

    def error_free(self, n, expr, deg):
        """An error-free tail (two_product, two_diff, two_sum): a double equal to expr."""
        self.defs.append(f"{n} = {expr};   # error-free tail")
        self.deg[n] = deg
        self.exact.add(n)
        self.order.append(n)

    def text(self, goals):
        out = list(self.header)
        out.append("")
        out.append("# ---- the computation, every quantity divided by the maxima of its degree ----")
        out += self.defs
        out.append("")
        out.append("{")
        hyp_lines = [f"{h}   # {t}" for h, t in self.hyps]
        out.append("     " + "\n  /\\ ".join(hyp_lines))
        goal_lines = [f"{g}   # {t}" for g, t in goals]
        out.append("  -> " + "\n  /\\ ".join(goal_lines))
        out.append("}")
        out.append("")
        out.append("# ---- hints: the error of each operation, split into the errors of its operands")
        out.append("# ---- and its own rounding (Gappa then bounds each term by interval arithmetic)")
        out += self.hints
        return "\n".join(out) + "\n"


def run_query(script, wanted):
    """wanted: list of expressions; returns dict expr -> max |bound| (Fraction)."""
    goals = [(f"{w} in ?", "query") for w in wanted]
    src = script.text(goals)
    src = re.sub(r"   # query", "", src)
    r = subprocess.run(["gappa"], input=src, capture_output=True, text=True)
    res = {}
    for line in (r.stdout + r.stderr).splitlines():
        m = re.match(r"\s*(.*) in \[(-?\d+)(?:b(-?\d+))?(?:\s*\{[^}]*\})?,\s*(-?\d+)(?:b(-?\d+))?", line)
        if m:
            lo = Fraction(int(m.group(2))) * Fraction(2) ** int(m.group(3) or 0)
            hi = Fraction(int(m.group(4))) * Fraction(2) ** int(m.group(5) or 0)
            res[m.group(1).strip()] = max(abs(lo), abs(hi))
    missing = [w for w in wanted if w not in res]
    if missing:
        sys.exit(f"{script.name}: gappa gave no enclosure for {missing}\n{r.stdout}\n{r.stderr}")
    return res


def finish(script, final, exports=(), target=None):
    """Query, then return the final text with proven goals. The @E goal bounds
    |final - target|, target being the exact counterpart of final unless given."""
    target = target or (script.cap(final) if final else None)
    wanted = ([f"{final} - {target}"] if final else []) + list(script.order)
    for e in exports:
        wanted += [f"{e} - {script.cap(e)}", script.cap(e)]
    wanted = list(dict.fromkeys(wanted))
    res = run_query(script, wanted)
    goals = []
    if final:
        E = round_up_double(res[f"{final} - {target}"])
        goals.append((f"|{final} - {target}| <= {hexf(E)}", "@E"))
    bydeg = {}
    for n in script.order:
        bydeg.setdefault(script.deg[n], Fraction(0))
        bydeg[script.deg[n]] = max(bydeg[script.deg[n]], res[n])
    exp = {}
    for e in exports:
        err = round_up_double(res[f"{e} - {script.cap(e)}"])
        rng = round_up_double(res[e])
        xr = round_up_double(res[script.cap(e)])
        exp[e] = (hexf(err), hexf(rng), hexf(xr))
        goals.append((f"|{e} - {script.cap(e)}| <= {hexf(err)}", f"@export {script.name}:{e}.err"))
        goals.append((f"|{e}| <= {hexf(rng)}", f"@export {script.name}:{e}.range"))
        goals.append((f"|{script.cap(e)}| <= {hexf(xr)}", f"@export {script.name}:{script.cap(e)}.range"))
    for n in script.order:
        k = script.deg[n]
        goals.append((f"|{n}| <= {hexf(pow2_above(bydeg[k]))}", f"@range degree={k}"))
    return script.text(goals), exp


# ----------------------------------------------------------------------------------------
def meta(pred, lower, upper, roundings, degree, extra):
    return [
        f"# Gappa proof of the {pred} filter bound of certimesh.",
        "# Models predicates/include/certimesh/predicates/detail/filters.h ("
        + pred + "_filter) operation by operation:",
        "# same operands, same order, binary64 round-to-nearest, no FMA. Derivation: proofs/README.md.",
        "# Generated by proofs/gappa/generate.py; checked by the CTest tests proofs.gappa."
        + pred + " and proofs.constants_match.",
        "#",
    ] + ["# " + x for x in extra] + [
        "#",
        f"# @predicate {pred}",
        f"# @lower_guard {lower}",
        f"# @upper_guard {upper}",
        f"# @bound_roundings {roundings}",
        f"# @degree {degree}",
    ]


def orient3d():
    lower, upper = -320, 330
    s = Script("orient3d", lower, meta("orient3d", f"0x1p{lower}", f"0x1p+{upper}", 3, 3, [
        "Normalization: differences divided by the maximum of their axis, each product by the",
        "product of its axes' maxima. Theorem: |fl(det) - det| <= E * maxx * maxy * maxz.",
        "Code constant: the binary64 value above E / (1 - 2^-53)^3.",
    ]))
    for a in "xyz":
        for p in "abc":
            s.diff(p + "d" + a, "max" + a)
    s.comment("det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady)")
    s.comment("      + cdx * (ady * bdz - adz * bdy), summed left to right")
    s.mul("s1", "bdy", "cdz"); s.mul("s2", "bdz", "cdy"); s.add("m1", "s1", "s2", "-")
    s.mul("s3", "cdy", "adz"); s.mul("s4", "cdz", "ady"); s.add("m2", "s3", "s4", "-")
    s.mul("s5", "ady", "bdz"); s.mul("s6", "adz", "bdy"); s.add("m3", "s5", "s6", "-")
    s.mul("t1", "adx", "m1"); s.mul("t2", "bdx", "m2"); s.mul("t3", "cdx", "m3")
    s.add("u1", "t1", "t2"); s.add("det", "u1", "t3")
    return [("orient3d", finish(s, "det")[0])]


def incircle():
    lower, upper = -240, 250
    s = Script("incircle", lower, meta("incircle", f"0x1p{lower}", f"0x1p+{upper}", 4, 4, [
        "Normalization: every difference divided by m = max(maxx, maxy), a quantity of degree",
        "k by m^k. Theorem: |fl(det) - det| <= E * m^4. Code constant: the binary64 value",
        "above E / (1 - 2^-53)^4 (m2 = fl(m*m) enters twice, then fl(fl(bound*m2)*m2)).",
    ]))
    for a in "xy":
        for p in "abc":
            s.diff(p + "d" + a, "m")
    s.comment("lifts: alift = adx * adx + ady * ady, ...")
    for p in "abc":
        s.mul(p + "xx", p + "dx", p + "dx"); s.mul(p + "yy", p + "dy", p + "dy")
        s.add(p + "lift", p + "xx", p + "yy")
    s.comment("det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy)")
    s.comment("      + clift * (adx * bdy - bdx * ady), summed left to right")
    s.mul("s1", "bdx", "cdy"); s.mul("s2", "cdx", "bdy"); s.add("m1", "s1", "s2", "-")
    s.mul("s3", "cdx", "ady"); s.mul("s4", "adx", "cdy"); s.add("m2", "s3", "s4", "-")
    s.mul("s5", "adx", "bdy"); s.mul("s6", "bdx", "ady"); s.add("m3", "s5", "s6", "-")
    s.mul("t1", "alift", "m1"); s.mul("t2", "blift", "m2"); s.mul("t3", "clift", "m3")
    s.add("u1", "t1", "t2"); s.add("det", "u1", "t3")
    return [("incircle", finish(s, "det")[0])]


def insphere():
    lower, upper = -190, 200
    common = [
        "Normalization: every difference divided by m = max(mx, my, mz), a quantity of degree",
        "k by m^k.",
    ]
    # Lemma 1: the four 3x3 minors abc, bcd, cda, dab.
    s1 = Script("insphere_minors", lower, [
        "# Lemma 1 of the insphere filter proof (the others: insphere_lifts.g, insphere.g):",
        "# the 3x3 minors abc, bcd, cda, dab of insphere_filter in",
        "# predicates/include/certimesh/predicates/detail/filters.h, same order, binary64",
        "# round-to-nearest, no FMA. Its @export goals are the @import hypotheses of insphere.g",
        "# (proofs.constants_match checks that they agree). Generated by proofs/gappa/generate.py.",
        "#"] + ["# " + x for x in common] + [
        "#",
        "# @lemma_of insphere",
        f"# @lower_guard 0x1p{lower}",
    ])
    for a in "xyz":
        for p in "abcd":
            s1.diff(p + "e" + a, "m")

    def minor(n, p, q):
        s1.mul(n + "_1", p + "ex", q + "ey"); s1.mul(n + "_2", q + "ex", p + "ey")
        s1.add(n, n + "_1", n + "_2", "-")

    s1.comment("2x2 minors: ab = aex * bey - bex * aey, ...")
    for n, p, q in [("ab", "a", "b"), ("bc", "b", "c"), ("cd", "c", "d"), ("da", "d", "a"),
                    ("ac", "a", "c"), ("bd", "b", "d")]:
        minor(n, p, q)

    def tri(n, terms):
        names = []
        for i, (sg, z, mn) in enumerate(terms):
            s1.mul(f"{n}_{i + 1}", z + "ez", mn)
            names.append((sg, f"{n}_{i + 1}"))
        s1.add(n + "_s", names[0][1], names[1][1], names[1][0])
        s1.add(n, n + "_s", names[2][1], names[2][0])

    s1.comment("abc = aez * bc - bez * ac + cez * ab, ... (summed left to right)")
    tri("abc", [("+", "a", "bc"), ("-", "b", "ac"), ("+", "c", "ab")])
    tri("bcd", [("+", "b", "cd"), ("-", "c", "bd"), ("+", "d", "bc")])
    tri("cda", [("+", "c", "da"), ("+", "d", "ac"), ("+", "a", "cd")])
    tri("dab", [("+", "d", "ab"), ("+", "a", "bd"), ("+", "b", "da")])
    t1, e1 = finish(s1, None, exports=["abc", "bcd", "cda", "dab"])

    # Lemma 2: the lifts.
    s2 = Script("insphere_lifts", lower, [
        "# Lemma 2 of the insphere filter proof: the lifts alift = aex*aex + aey*aey + aez*aez,",
        "# ... of insphere_filter, same order, binary64 round-to-nearest, no FMA. Its @export",
        "# goals are @import hypotheses of insphere.g. Generated by proofs/gappa/generate.py.",
        "#"] + ["# " + x for x in common] + [
        "#",
        "# @lemma_of insphere",
        f"# @lower_guard 0x1p{lower}",
    ])
    for a in "xyz":
        for p in "abcd":
            s2.diff(p + "e" + a, "m")
    for p in "abcd":
        s2.mul(p + "xx", p + "ex", p + "ex"); s2.mul(p + "yy", p + "ey", p + "ey")
        s2.mul(p + "zz", p + "ez", p + "ez")
        s2.add(p + "l2", p + "xx", p + "yy"); s2.add(p + "lift", p + "l2", p + "zz")
    t2, e2 = finish(s2, None, exports=["alift", "blift", "clift", "dlift"])

    # Main: det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd)
    s3 = Script("insphere", lower, meta("insphere", f"0x1p{lower}", f"0x1p+{upper}", 5, 5, common + [
        "Theorem: |fl(det) - det| <= E * m^5, from the minors and lifts proven in",
        "insphere_minors.g and insphere_lifts.g (imported as hypotheses). Code constant: the",
        "binary64 value above E / (1 - 2^-53)^5 (m2 = fl(m*m) enters twice, then three more",
        "roundings in fl(fl(fl(bound*m2)*m2)*m)).",
    ]))
    s3.defs.append("# inputs: the minors (degree 3) and lifts (degree 2), with their exact values")
    for n in ["abc", "bcd", "cda", "dab"]:
        s3.imported(n, 3, *e1[n], "insphere_minors")
    for n in ["alift", "blift", "clift", "dlift"]:
        s3.imported(n, 2, *e2[n], "insphere_lifts")
    s3.comment("det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd)")
    s3.mul("w1", "dlift", "abc"); s3.mul("w2", "clift", "dab"); s3.add("v1", "w1", "w2", "-")
    s3.mul("w3", "blift", "cda"); s3.mul("w4", "alift", "bcd"); s3.add("v2", "w3", "w4", "-")
    s3.add("det", "v1", "v2")
    t3, _ = finish(s3, "det")
    return [("insphere_minors", t1), ("insphere_lifts", t2), ("insphere", t3)]


# ---- second stages of the exact predicates (predicates/src/orient2d.cpp, orient3d.cpp) ----
def meta_stage2(pred, lower, upper, roundings, degree, source, function, extra):
    return [
        f"# Gappa proof of the {pred} second-stage bound of certimesh.",
        f"# Models {function} in predicates/src/{source} operation by operation: same",
        "# operands, same order, binary64 round-to-nearest, no FMA. Derivation: proofs/README.md,",
        "# section 9. Generated by proofs/gappa/generate.py; checked by the CTest tests",
        f"# proofs.gappa.{pred}_stage2 and proofs.constants_match.",
        "#",
        "# The stage rounds each coordinate difference to h and keeps its exact tail t",
        "# (two_diff: h + t is the exact difference). It computes E = det(h) exactly (expansion",
        "# arithmetic) plus `correction`, the first-order change of det(h) under h -> h + t,",
        "# evaluated in double. The sign of E is certified when |E| > bound * (product of the",
        "# per-axis maxima of |h|), compared exactly. The true determinant is det(h + t), so the",
        "# proof bounds |correction - (det(h + t) - det(h))|: the rounding error of the",
        "# correction plus the exact higher-order tail terms.",
        "#",
    ] + ["# " + x for x in extra] + [
        "#",
        f"# @predicate {pred}_stage2",
        f"# @constant {pred}_stage2_bound",
        f"# @guards {pred}",
        f"# @lower_guard {lower}",
        f"# @upper_guard {upper}",
        f"# @bound_roundings {roundings}",
        f"# @degree {degree}",
    ]


def det3_text(r1, r2, r3):
    """det[r1; r2; r3], rows (x, y, z), in the form of the filter (expanded along x)."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = r1, r2, r3
    return (f"({x1} * ({y2} * {z3} - {z2} * {y3}) + {x2} * ({y3} * {z1} - {z3} * {y1})"
            f" + {x3} * ({y1} * {z2} - {z1} * {y2}))")


def orient2d_stage2():
    lower, upper = -480, 500
    s = Script("orient2d_stage2", lower, meta_stage2(
        "orient2d", f"0x1p{lower}", f"0x1p+{upper}", 2, 2, "orient2d.cpp", "orient2d_second_stage", [
            "Normalization: x differences and their tails divided by maxx, y ones by maxy, every",
            "product by maxx*maxy; maxx, maxy are maxima of the rounded |h|, so |h| <= 1, and",
            "|t| <= ulp(h)/2 <= 2^-53 |h|. Theorem: |correction - (det(h+t) - det(h))| <= E * maxx",
            "* maxy. Code constant: orient2d_stage2_bound, from E by the rule of section 3 with",
            "r = 2 (fl(fl(bound * maxx) * maxy)); its last rounding can underflow at the lower",
            "guard, which check_constants.py charges as described in section 9.",
        ]))
    for n, ax in (("acx", "maxx"), ("bcx", "maxx"), ("acy", "maxy"), ("bcy", "maxy")):
        s.rounded_diff(n, ax)
    for n, ax in (("acx", "maxx"), ("bcx", "maxx"), ("acy", "maxy"), ("bcy", "maxy")):
        s.tail(n + "_t", n, ax)
    s.comment("correction = (acx * bcy_t + bcy * acx_t) - (acy * bcx_t + bcx * acy_t)")
    s.mul("q1", "acx", "bcy_t"); s.mul("q2", "bcy", "acx_t"); s.add("s1", "q1", "q2")
    s.mul("q3", "acy", "bcx_t"); s.mul("q4", "bcx", "acy_t"); s.add("s2", "q3", "q4")
    s.capmap["correction"] = "Lin"
    s.add("correction", "s1", "s2", "-")
    s.comment("the exact change det(h + t) - det(h) = Lin + Quad, det = acx * bcy - acy * bcx")
    s.defs.append("Quad = acx_t * bcy_t - acy_t * bcx_t;")
    s.defs.append("Change = ((acx + acx_t) * (bcy + bcy_t) - (acy + acy_t) * (bcx + bcx_t))"
                  " - (acx * bcy - acy * bcx);")
    s.hints.insert(0, "correction - Change -> (correction - Lin) - Quad;")
    return [("orient2d_stage2", finish(s, "correction", target="Change")[0])]


def orient3d_correction(s):
    """The rounded differences, their tails, the nine cofactors and the first-order
    correction of orient3d's second stage (orient3d.cpp, first_order_correction)."""
    rows = {p: [p + "d" + a for a in "xyz"] for p in "abc"}
    for p in "abc":
        for n, ax in zip(rows[p], ("maxx", "maxy", "maxz")):
            s.rounded_diff(n, ax)
    for p in "abc":
        for n, ax in zip(rows[p], ("maxx", "maxy", "maxz")):
            s.tail(n + "_t", n, ax)
    s.comment("cofactors of h: cax = bdy * cdz - bdz * cdy, cay = bdz * cdx - bdx * cdz, ...")
    cof = [("cax", "bdy", "cdz", "bdz", "cdy"), ("cay", "bdz", "cdx", "bdx", "cdz"),
           ("caz", "bdx", "cdy", "bdy", "cdx"), ("cbx", "cdy", "adz", "cdz", "ady"),
           ("cby", "cdz", "adx", "cdx", "adz"), ("cbz", "cdx", "ady", "cdy", "adx"),
           ("ccx", "ady", "bdz", "adz", "bdy"), ("ccy", "adz", "bdx", "adx", "bdz"),
           ("ccz", "adx", "bdy", "ady", "bdx")]
    for n, a, b, c, d in cof:
        s.mul(n + "_1", a, b); s.mul(n + "_2", c, d); s.add(n, n + "_1", n + "_2", "-")
    s.comment("correction = (((t0*cax + t1*cay) + t2*caz) + ((t3*cbx + t4*cby) + t5*cbz))")
    s.comment("             + ((t6*ccx + t7*ccy) + t8*ccz),  t = (adx_t, ady_t, adz_t, bdx_t, ...)")
    tails = [n + "_t" for p in "abc" for n in rows[p]]
    for i, (t, (c, *_)) in enumerate(zip(tails, cof)):
        s.mul(f"p{i}", t, c)
    s.add("g1", "p0", "p1"); s.add("g2", "g1", "p2")
    s.add("g3", "p3", "p4"); s.add("g4", "g3", "p5"); s.add("g5", "g2", "g4")
    s.add("g6", "p6", "p7"); s.add("g7", "g6", "p8")
    s.capmap["correction"] = "Lin"
    s.add("correction", "g5", "g7")
    A, B, C = rows["a"], rows["b"], rows["c"]
    tA, tB, tC = ([n + "_t" for n in r] for r in (A, B, C))
    s.comment("the exact change det(h + t) - det(h) = Lin + Quad + Cub (det is linear in each row)")
    s.defs.append(f"Quad = {det3_text(tA, tB, C)}\n     + {det3_text(tA, B, tC)}\n"
                  f"     + {det3_text(A, tB, tC)};")
    s.defs.append(f"Cub = {det3_text(tA, tB, tC)};")
    ex = [[f"({h} + {h}_t)" for h in r] for r in (A, B, C)]
    return rows, ex


def orient3d_stage2():
    lower, upper = -320, 330
    s = Script("orient3d_stage2", lower, meta_stage2(
        "orient3d", f"0x1p{lower}", f"0x1p+{upper}", 3, 3, "orient3d.cpp",
        "first_order_correction and second_stage", [
            "Normalization: differences and tails divided by the maximum of their axis (of the",
            "rounded |h|, so |h| <= 1, |t| <= 2^-53 |h|), each product by the product of its",
            "axes' maxima. Theorem: |correction - (det(h+t) - det(h))| <= E * maxx * maxy * maxz.",
            "Code constant: orient3d_stage2_bound, from E by the rule of section 3 with r = 3; its",
            "last rounding can underflow at the lower guard (section 9).",
        ]))
    rows, ex = orient3d_correction(s)
    A, B, C = rows["a"], rows["b"], rows["c"]
    s.defs.append(f"Change = {det3_text(*ex)}\n       - {det3_text(A, B, C)};")
    s.hints.insert(0, "correction - Change -> (correction - Lin) - (Quad + Cub);")
    return [("orient3d_stage2", finish(s, "correction", target="Change")[0])]


def orient3d_compensated():
    lower, upper = -320, 330
    s = Script("orient3d_compensated", lower, [
        "# Gappa proof of the orient3d compensated-stage bound of certimesh.",
        "# Models first_order_correction and compensated_stage in predicates/src/orient3d.cpp",
        "# operation by operation: same operands, same order, binary64 round-to-nearest, no FMA.",
        "# Derivation: proofs/README.md, section 11. Generated by proofs/gappa/generate.py;",
        "# checked by the CTest tests proofs.gappa.orient3d_compensated and",
        "# proofs.constants_match.",
        "#",
        "# The stage evaluates det(h) in double-double: each x-column cofactor m = fl(p - q) of",
        "# rounded products p, q keeps the error-free tails pe, qe (two_product) and me",
        "# (two_diff) as ml = fl(me + fl(pe - qe)); each term h * m is split by two_product into",
        "# s + se, and lo_a = fl(se + fl(h * ml)); the three s are added by two_sum (tails xe,",
        "# ye) into y. lo adds the tails, the lo_a and the second stage's first-order correction",
        "# in double. The pair (y, lo) approximates the true determinant det(h + t); the code",
        "# certifies the sign of est = fl(y + lo) when |est| > bound * maxx * maxy * maxz.",
        "#",
        "# Normalization as in orient3d_stage2.g. Theorem: |(y + lo) - det(h + t)| <= E *",
        "# maxx * maxy * maxz. Code constant: orient3d_compensated_bound, from E by the rule of",
        "# section 3 with r = 3 + 1 (the three roundings of the bound and the relative rounding",
        "# of est; section 11), with the charge of section 9 for an underflowing last rounding.",
        "#",
        "# @predicate orient3d_compensated",
        "# @constant orient3d_compensated_bound",
        "# @guards orient3d",
        f"# @lower_guard 0x1p{lower}",
        f"# @upper_guard 0x1p+{upper}",
        "# @bound_roundings 3",
        "# @estimate_roundings 1",
        "# @degree 3",
    ])
    rows, ex = orient3d_correction(s)
    s.comment("det(h) in double-double along the x column: adx * cax + bdx * cbx + cdx * ccx")
    for h, m in (("adx", "cax"), ("bdx", "cbx"), ("cdx", "ccx")):
        s.error_free(f"{m}_pe", f"{m.capitalize()}_1 - {m}_1", 2)
        s.error_free(f"{m}_qe", f"{m.capitalize()}_2 - {m}_2", 2)
        s.error_free(f"{m}_me", f"({m}_1 - {m}_2) - {m}", 2)
        s.add(f"{m}_d", f"{m}_pe", f"{m}_qe", "-")
        s.add(f"{m}_l", f"{m}_me", f"{m}_d")
        s.mul(f"{h}_s", h, m)
        s.error_free(f"{h}_se", f"{h} * {m} - {h}_s", 3)
        s.mul(f"{h}_ml", h, f"{m}_l")
        s.add(f"{h}_lo", f"{h}_se", f"{h}_ml")
    s.add("x", "adx_s", "bdx_s")
    s.error_free("x_e", "(adx_s + bdx_s) - x", 3)
    s.add("y", "x", "cdx_s")
    s.error_free("y_e", "(x + cdx_s) - y", 3)
    s.add("l12", "adx_lo", "bdx_lo")
    s.add("l123", "l12", "cdx_lo")
    s.add("xye", "x_e", "y_e")
    s.add("l", "xye", "l123")
    s.add("lo", "l", "correction")
    s.defs.append(f"Full = {det3_text(*ex)};   # det(h + t), the true determinant")
    s.defs.append("Pair = y + lo;   # the double-double result")
    s.hints.insert(0, "Pair - Full -> (lo - Lo) - (Quad + Cub);")
    return [("orient3d_compensated", finish(s, "Pair", target="Full")[0])]


def incircle_higher_order():
    """det(h + t) - det(h) - (its first-order part), factored: with lift(h + t) = L + L1 +
    L2 and minor(h + t) = M + M1 + M2 split by their degree in the tails, the terms of
    sum (L + L1 + L2)(M + M1 + M2) with two or more tail factors. Factored rather than
    expanded into monomials: Gappa and Coq check it much faster."""
    terms = []
    for p, q, r in (("a", "b", "c"), ("b", "c", "a"), ("c", "a", "b")):
        L = f"({p}dx * {p}dx + {p}dy * {p}dy)"
        L1 = f"(2 * ({p}dx * {p}dx_t + {p}dy * {p}dy_t))"
        L2 = f"({p}dx_t * {p}dx_t + {p}dy_t * {p}dy_t)"
        M = f"({q}dx * {r}dy - {r}dx * {q}dy)"
        M1 = f"(({q}dx * {r}dy_t + {r}dy * {q}dx_t) - ({q}dy * {r}dx_t + {r}dx * {q}dy_t))"
        M2 = f"({q}dx_t * {r}dy_t - {r}dx_t * {q}dy_t)"
        terms.append(f"({L} * {M2} + {L1} * ({M1} + {M2}) + {L2} * ({M} + {M1} + {M2}))")
    return "\n     + ".join(terms)


def incircle_compensated():
    lower, upper = -240, 250
    s = Script("incircle_compensated", lower, [
        "# Gappa proof of the incircle compensated-stage bound of certimesh.",
        "# Models first_order_correction and compensated_stage in predicates/src/incircle.cpp",
        "# operation by operation: same operands, same order, binary64 round-to-nearest, no FMA.",
        "# Derivation: proofs/README.md, section 12. Generated by proofs/gappa/generate.py;",
        "# checked by the CTest tests proofs.gappa.incircle_compensated and",
        "# proofs.constants_match.",
        "#",
        "# The stage rounds each coordinate difference to h and keeps its exact tail t",
        "# (two_diff), and evaluates det(h) = sum over (p, q, r) cyclic in (a, b, c) of",
        "# plift * pm, plift = pdx^2 + pdy^2, pm = qdx * rdy - rdx * qdy, in double-double:",
        "# plift and pm are rounded sums with their error-free tails gathered in plift_l and",
        "# pm_l; plift * pm is split by two_product into p_s + p_se, and p_lo = fl(p_se +",
        "# fl(fl(plift * pm_l) + fl(plift_l * pm))) (plift_l * pm_l is neglected and bounded);",
        "# the three p_s are added by two_sum (tails x_e, y_e) into y. lo adds the tails, the",
        "# p_lo and the first-order tail correction in double. The pair (y, lo) approximates",
        "# the true determinant det(h + t); the code certifies the sign of est = fl(y + lo)",
        "# when |est| > bound * m2 * m2, m2 = fl(m * m), m the largest |h| over both axes.",
        "#",
        "# Normalization: h and t divided by m (|h| <= 1, |t| <= 2^-53 |h|), a quantity of",
        "# degree k by m^k. Theorem: |(y + lo) - det(h + t)| <= E * m^4. Code constant:",
        "# incircle_compensated_bound, from E by the rule of section 3 with r = 4 + 1 (m2",
        "# twice and two more roundings in the bound, the relative rounding of est;",
        "# section 11), with the charge of section 9 for an underflowing last rounding.",
        "#",
        "# @predicate incircle_compensated",
        "# @constant incircle_compensated_bound",
        "# @guards incircle",
        f"# @lower_guard 0x1p{lower}",
        f"# @upper_guard 0x1p+{upper}",
        "# @bound_roundings 4",
        "# @estimate_roundings 1",
        "# @degree 4",
    ])
    names = [p + "d" + a for p in "abc" for a in "xy"]
    for n in names:
        s.rounded_diff(n, "m")
    for n in names:
        s.tail(n + "_t", n, "m")
    cyc = (("a", "b", "c"), ("b", "c", "a"), ("c", "a", "b"))
    s.comment("lifts plift = pdx * pdx + pdy * pdy and minors pm = qdx * rdy - rdx * qdy")
    for p, q, r in cyc:
        s.mul(p + "xx", p + "dx", p + "dx"); s.mul(p + "yy", p + "dy", p + "dy")
        s.add(p + "lift", p + "xx", p + "yy")
        s.mul(p + "m_1", q + "dx", r + "dy"); s.mul(p + "m_2", r + "dx", q + "dy")
        s.add(p + "m", p + "m_1", p + "m_2", "-")
    s.comment("first-order correction, per p: plift * ((qdx * rdy_t + rdy * qdx_t)")
    s.comment("  - (qdy * rdx_t + rdx * qdy_t)) + 2 (pdx * pdx_t + pdy * pdy_t) * pm")
    for p, q, r in cyc:
        s.mul(p + "c1", q + "dx", r + "dy_t"); s.mul(p + "c2", r + "dy", q + "dx_t")
        s.add(p + "c12", p + "c1", p + "c2")
        s.mul(p + "c3", q + "dy", r + "dx_t"); s.mul(p + "c4", r + "dx", q + "dy_t")
        s.add(p + "c34", p + "c3", p + "c4")
        s.add(p + "cm", p + "c12", p + "c34", "-")
        s.mul(p + "k1", p + "lift", p + "cm")
        s.mul(p + "e1", p + "dx", p + "dx_t"); s.mul(p + "e2", p + "dy", p + "dy_t")
        s.add(p + "e", p + "e1", p + "e2")
        s.add(p + "e2x", p + "e", p + "e")
        s.mul(p + "k2", p + "e2x", p + "m")
        s.add(p + "corr", p + "k1", p + "k2")
    s.add("corr_ab", "acorr", "bcorr")
    s.capmap["correction"] = "Lin"
    s.add("correction", "corr_ab", "ccorr")
    s.comment("det(h) in double-double")
    for p, q, r in cyc:
        s.error_free(p + "xx_e", f"{p}dx * {p}dx - {p}xx", 2)
        s.error_free(p + "yy_e", f"{p}dy * {p}dy - {p}yy", 2)
        s.error_free(p + "lift_se", f"({p}xx + {p}yy) - {p}lift", 2)
        s.add(p + "lift_d", p + "xx_e", p + "yy_e")
        s.add(p + "lift_l", p + "lift_se", p + "lift_d")
        s.error_free(p + "m_pe", f"{q}dx * {r}dy - {p}m_1", 2)
        s.error_free(p + "m_qe", f"{r}dx * {q}dy - {p}m_2", 2)
        s.error_free(p + "m_me", f"({p}m_1 - {p}m_2) - {p}m", 2)
        s.add(p + "m_d", p + "m_pe", p + "m_qe", "-")
        s.add(p + "m_l", p + "m_me", p + "m_d")
        s.mul(p + "_s", p + "lift", p + "m")
        s.error_free(p + "_se", f"{p}lift * {p}m - {p}_s", 4)
        s.mul(p + "_a", p + "lift", p + "m_l")
        s.mul(p + "_b", p + "lift_l", p + "m")
        s.add(p + "_ab", p + "_a", p + "_b")
        s.add(p + "_lo", p + "_se", p + "_ab")
    s.add("x", "a_s", "b_s")
    s.error_free("x_e", "(a_s + b_s) - x", 4)
    s.add("y", "x", "c_s")
    s.error_free("y_e", "(x + c_s) - y", 4)
    s.add("l12", "a_lo", "b_lo")
    s.add("l123", "l12", "c_lo")
    s.add("xye", "x_e", "y_e")
    s.add("l", "xye", "l123")
    s.add("lo", "l", "correction")
    s.comment("the exact change det(h + t) - det(h) = Lin + HO; the neglected products")
    s.defs.append(f"HO = {incircle_higher_order()};")
    s.defs.append("Neg = Alift_l * Am_l + Blift_l * Bm_l + Clift_l * Cm_l;")
    ex = {n: f"({n} + {n}_t)" for n in names}

    def det_text(x):
        lift = {p: f"({x[p + 'dx']} * {x[p + 'dx']} + {x[p + 'dy']} * {x[p + 'dy']})" for p in "abc"}
        mnr = {p: f"({x[q + 'dx']} * {x[r + 'dy']} - {x[r + 'dx']} * {x[q + 'dy']})" for p, q, r in cyc}
        return " + ".join(f"{lift[p]} * {mnr[p]}" for p in "abc")
    s.defs.append(f"Full = {det_text(ex)};   # det(h + t), the true determinant")
    s.defs.append("Pair = y + lo;   # the double-double result")
    s.hints.insert(0, "Pair - Full -> (lo - Lo) + Neg - HO;")
    return [("incircle_compensated", finish(s, "Pair", target="Full")[0])]


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    dry = "--dry-run" in sys.argv
    # orient2d_ozaki.g (the orient2d filter) is written by hand: README section 10.
    gens = {"orient3d": orient3d, "incircle": incircle, "insphere": insphere,
            "orient2d_stage2": orient2d_stage2, "orient3d_stage2": orient3d_stage2,
            "orient3d_compensated": orient3d_compensated,
            "incircle_compensated": incircle_compensated}
    for name in (args or list(gens)):
        for fname, text in gens[name]():
            path = os.path.join(HERE, fname + ".g")
            if dry:
                sys.stdout.write(f"==== {path}\n{text}")
            else:
                with open(path, "w") as f:
                    f.write(text)
                print("wrote", path)


if __name__ == "__main__":
    main()
