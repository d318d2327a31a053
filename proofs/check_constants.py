#!/usr/bin/env python3
"""proofs.constants_match: fail unless every constant in filter_constants.h is the value
its Gappa proof establishes, and unless each proof's model parameters match its guards.

For each predicate P (proofs/gappa/P.g, plus the lemma files it imports):
  * P_error_bound  == the binary64 number just above E / (1 - 2^-53)^r, i.e. rounded up,
    where E is the bound of the goal tagged @E and r is @bound_roundings (the roundings
    of the bound's own computation in filters.h, each of which can lose a factor 1 - 2^-53);
  * P_lower_guard == @lower_guard, P_upper_guard == @upper_guard;
  * every @delta hypothesis is |d| <= 2^-53 (unit roundoff of binary64 round-to-nearest);
  * every @diff hypothesis is |T| <= 1 + 2^-53 (an exact difference over the maximum of the
    rounded ones);
  * every @eta hypothesis of degree k is at least 2^-1074 / lower_guard^k (underflow);
  * every computed quantity has a @range goal of its degree k, and range * upper_guard^k
    <= 2^1023 (no overflow);
  * the bound's own computation neither underflows nor overflows:
    bound * lower_guard^j >= 2^-1022 and bound * upper_guard^j <= 2^1023 for j <= degree,
    and lower_guard^2 >= 2^-1022 (the m*m of incircle/insphere);
  * every @import hypothesis is implied by the @export goal with the same key.
The second stages of the exact predicates (proofs/gappa/P_stage2.g, P in STAGE2) are checked
the same way, with @constant naming their constant (P_stage2_bound) and @guards the filter
whose guards they share; in addition every @rounded_diff hypothesis is |h| <= 1 (a rounded
difference over the maximum of the rounded ones) and every @tail hypothesis is
|e| <= 2^-53 (a two_diff tail relative to its rounded difference).
When the last rounding of the bound's computation can underflow at the lower guard
(bound * lower_guard^degree < 2^-1022; only the second stages), that rounding can lose an
absolute 2^-1075 instead of a factor 1 - 2^-53, and the constant must be the double above
(E + 2^-1074 / lower_guard^degree) / (1 - 2^-53)^r (proofs/README.md, section 9); the
earlier roundings must stay normal.
The compensated stages of orient3d and incircle (proofs/gappa/orient3d_compensated.g,
incircle_compensated.g, README sections 11 and 12) are checked like a second stage, with r = @bound_roundings + @estimate_roundings: its
certification compares the rounded estimate fl(y + lo), whose relative rounding costs one
more factor (1 - 2^-53).
The orient2d filter has Ozaki et al.'s shape (proofs/gappa/orient2d_ozaki.g, README section
10) and its own check (check_ozaki): orient2d_theta and orient2d_underflow_bound equal the
script's @theta and @underflow_bound, which are the literals its computation uses; theta is
the double above (1/(1 - u)^3 - 1)(1 + u)/(1 - u)^3; the model's hypotheses are the standard
ones (|d| <= 2^-53, |eta| <= 2^-1075, dl, dr over all finite non-negative doubles) and the
theorem is that the exact determinant is positive.
Exact rational arithmetic throughout.  Usage: check_constants.py <filter_constants.h> <gappa dir>
"""
import os
import re
import sys
from fractions import Fraction

PREDICATES = ["orient3d", "incircle", "insphere"]
OZAKI = "orient2d_ozaki"  # the orient2d filter: its own shape, checked by check_ozaki
STAGE2 = ["orient2d_stage2", "orient3d_stage2"]
# Stages whose certification compares a rounded estimate: its relative rounding adds
# @estimate_roundings factors (1 - 2^-53) to the rule (README section 11).
COMPENSATED = ["orient3d_compensated", "incircle_compensated"]
U = Fraction(1, 2 ** 53)
TWO = Fraction(2)
errors = []


def fail(msg):
    errors.append(msg)


def parse_num(tok):
    """Exact value of a C/Gappa numeric literal: hex float, decimal, or Gappa's NbE."""
    tok = tok.strip()
    neg = tok.startswith("-")
    if neg or tok.startswith("+"):
        tok = tok[1:]
    m = re.fullmatch(r"0[xX]([0-9a-fA-F]*)(?:\.([0-9a-fA-F]*))?[pP]([+-]?\d+)", tok)
    if m:
        ip, fp, e = m.group(1) or "0", m.group(2) or "", int(m.group(3))
        v = Fraction(int(ip + fp, 16), 16 ** len(fp)) * TWO ** e
    elif re.fullmatch(r"\d+b[+-]?\d+", tok):
        a, b = tok.split("b")
        v = Fraction(int(a)) * TWO ** int(b)
    else:
        v = Fraction(tok)
    return -v if neg else v


def round_up_double(q):
    e = 0
    while q >= TWO ** (e + 1):
        e += 1
    while q < TWO ** e:
        e -= 1
    ulp = TWO ** (e - 52)
    return -(-q // ulp) * ulp


def is_double(q):
    return q > 0 and round_up_double(q) == q


def read_header(path):
    consts = {}
    for m in re.finditer(r"inline\s+constexpr\s+double\s+(\w+)\s*=\s*([^;]+);", open(path).read()):
        consts[m.group(1)] = (m.group(2).strip(), parse_num(m.group(2)))
    return consts


class GFile:
    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)[:-2]
        text = open(path).read()
        self.meta = dict(re.findall(r"^#\s*@(\w+)\s+(\S+)\s*$", text, re.M))
        self.hyps, self.goals = [], []
        body = text[text.index("{") + 1:text.index("}")]
        hyp_part, goal_part = body.split("->", 1)
        for part, dest in ((hyp_part, self.hyps), (goal_part, self.goals)):
            for line in part.splitlines():
                m = re.match(r"\s*(?:/\\)?\s*\|(.+)\|\s*<=\s*(\S+)\s*#\s*@(.*)$", line)
                if m:
                    dest.append((m.group(1).strip(), parse_num(m.group(2)), m.group(3).strip()))
                elif line.strip() and not line.strip().startswith("#"):
                    fail(f"{self.name}.g: unrecognized proposition line: {line.strip()}")
        # quantities computed in floating point: lowercase definitions
        self.computed = re.findall(r"^([a-z]\w*)\s*=", text, re.M)
        self.lower = parse_num(self.meta["lower_guard"]) if "lower_guard" in self.meta else None
        self.upper = parse_num(self.meta["upper_guard"]) if "upper_guard" in self.meta else None

    def tagged(self, lst, prefix):
        return [(e, v, t) for e, v, t in lst if t.split()[0] == prefix]


def check_model(g, lower, upper):
    for e, v, t in g.tagged(g.hyps, "delta"):
        if v != U:
            fail(f"{g.name}.g: |{e}| <= {v}: a rounding's relative error must be 2^-53")
    for e, v, t in g.tagged(g.hyps, "rounded_diff"):
        if v != 1:
            fail(f"{g.name}.g: |{e}| <= {v}: a rounded difference over its axis maximum is bounded by 1")
    for e, v, t in g.tagged(g.hyps, "tail"):
        if v != U:
            fail(f"{g.name}.g: |{e}| <= {v}: a tail is at most 2^-53 times its rounded difference")
    for e, v, t in g.tagged(g.hyps, "diff"):
        if v != 1 + U:
            fail(f"{g.name}.g: |{e}| <= {v}: a normalized difference is bounded by 1 + 2^-53")
    for e, v, t in g.tagged(g.hyps, "eta"):
        k = int(re.search(r"degree=(\d+)", t).group(1))
        need = TWO ** -1074 / lower ** k
        if v < need:
            fail(f"{g.name}.g: |{e}| <= {v}: an underflow of degree {k} can reach 2^-1074/lower^{k} = {need}")
    ranged = {}
    for e, v, t in g.tagged(g.goals, "range"):
        k = int(re.search(r"degree=(\d+)", t).group(1))
        ranged[e] = k
        if upper is not None and v * upper ** k > TWO ** 1023:
            fail(f"{g.name}.g: |{e}| <= {v} (degree {k}) may overflow below upper_guard {upper}")
    for c in g.computed:
        if c not in ranged:
            fail(f"{g.name}.g: computed quantity {c} has no @range goal (overflow unchecked)")


def check_ozaki(path, consts):
    text = open(path).read()
    meta = dict(re.findall(r"^#\s*@(\w+)\s+(\S+)\s*$", text, re.M))
    theta, under = parse_num(meta.get("theta", "0")), parse_num(meta.get("underflow_bound", "0"))
    if meta.get("predicate") != OZAKI:
        fail(f"{OZAKI}.g: @predicate is {meta.get('predicate')}")
    for key, want in (("orient2d_theta", theta), ("orient2d_underflow_bound", under)):
        if key not in consts:
            fail(f"filter_constants.h: {key} missing")
        elif consts[key][1] != want:
            fail(f"filter_constants.h: {key} = {consts[key][0]} but its proof gives "
                 f"{float(want).hex()} ({float(want)!r})")
    rule = round_up_double((1 / (1 - U) ** 3 - 1) * (1 + U) / (1 - U) ** 3)
    if theta != rule:
        fail(f"{OZAKI}.g: @theta {float(theta).hex()} is not the derived {float(rule).hex()}")
    body = "\n".join(l.split("#")[0] for l in text.splitlines())
    # The computation must use exactly these constants (the hint repeats them).
    m_t = re.search(r"^t\s*=\s*(\S+)\s*\*\s*s\s*\*\s*\(1 \+ d_t\)\s*\+\s*eta_t;", body, re.M)
    m_b = re.search(r"^bound\s*=\s*\(t\s*\+\s*(\S+)\)\s*\*\s*\(1 \+ d_bound\);", body, re.M)
    if not m_t or parse_num(m_t.group(1)) != theta:
        fail(f"{OZAKI}.g: the computation of t does not use @theta")
    if not m_b or parse_num(m_b.group(1)) != under:
        fail(f"{OZAKI}.g: the computation of bound does not use @underflow_bound")
    props = body[body.index("{") + 1:body.index("}")]
    hyps, goal = props.split("->")
    for m in re.finditer(r"\|(\w+)\|\s*<=\s*(\S+)", hyps):
        name, v = m.group(1), parse_num(m.group(2))
        want = U if name.startswith("d_") else TWO ** -1075 if name.startswith("eta_") else None
        if v != want:
            fail(f"{OZAKI}.g: |{name}| <= {m.group(2)} is not the standard model")
    for var in ("dl", "dr"):
        if not re.search(rf"\b{var} in \[0, 0x1p1024\]", hyps):
            fail(f"{OZAKI}.g: {var} must range over all finite non-negative doubles")
    if not re.search(r"\bdet - bound >= 0\b", hyps):
        fail(f"{OZAKI}.g: the certification hypothesis must be det - bound >= 0")
    m_g = re.fullmatch(r"\s*Det\s*>=\s*(\S+)\s*", goal)
    if not m_g or parse_num(m_g.group(1)) <= 0:
        fail(f"{OZAKI}.g: the theorem must be Det >= (a positive number)")
    print(f"orient2d (Ozaki): theta = {float(theta).hex()} = {float(theta)!r}, "
          f"underflow_bound = {float(under).hex()}")


def main():
    header, gdir = sys.argv[1], sys.argv[2]
    consts = read_header(header)
    files = {}
    for fn in sorted(os.listdir(gdir)):
        if fn.endswith(".g") and fn != OZAKI + ".g":
            files[fn[:-2]] = GFile(os.path.join(gdir, fn))
    exports = {}
    for g in files.values():
        for e, v, t in g.tagged(g.goals, "export"):
            exports[t.split()[1]] = (e, v)
    if os.path.exists(os.path.join(gdir, OZAKI + ".g")):
        check_ozaki(os.path.join(gdir, OZAKI + ".g"), consts)
    else:
        fail(f"missing proof proofs/gappa/{OZAKI}.g")
    for p in PREDICATES + STAGE2 + COMPENSATED:
        if p not in files:
            fail(f"missing proof proofs/gappa/{p}.g")
            continue
        g = files[p]
        if g.meta.get("predicate") != p:
            fail(f"{p}.g: @predicate is {g.meta.get('predicate')}")
        constant = g.meta.get("constant", f"{p}_error_bound")
        guards = g.meta.get("guards", p)
        if p in STAGE2 and (constant != f"{p}_bound" or guards + "_stage2" != p):
            fail(f"{p}.g: @constant {constant} / @guards {guards} do not name {p}_bound / its filter")
        if p in COMPENSATED and (constant != f"{p}_bound" or not p.startswith(guards + "_")):
            fail(f"{p}.g: @constant {constant} / @guards {guards} do not name {p}_bound / its filter")
        lemmas = [f for f in files.values() if f.meta.get("lemma_of") == p]
        E = [v for e, v, t in g.tagged(g.goals, "E")]
        if len(E) != 1:
            fail(f"{p}.g: needs exactly one @E goal")
            continue
        E = E[0]
        r = int(g.meta["bound_roundings"]) + int(g.meta.get("estimate_roundings", "0"))
        if p in COMPENSATED and g.meta.get("estimate_roundings") != "1":
            fail(f"{p}.g: the estimate fl(y + lo) is one more rounding: @estimate_roundings 1")
        deg = int(g.meta["degree"])
        L, Up = g.lower, g.upper
        code = round_up_double(E / (1 - U) ** r)
        last_underflows = code * L ** deg < TWO ** -1022
        if last_underflows:
            # The last rounding of the bound's computation may be subnormal: it then loses up
            # to 2^-1075 absolutely, i.e. up to 2^-1075 / lower_guard^deg after normalization.
            code = round_up_double((E + TWO ** -1074 / L ** deg) / (1 - U) ** r)
        for key, want in ((constant, code), (f"{guards}_lower_guard", L),
                          (f"{guards}_upper_guard", Up)):
            if key not in consts:
                fail(f"filter_constants.h: {key} missing")
            elif consts[key][1] != want:
                fail(f"filter_constants.h: {key} = {consts[key][0]} but its proof gives "
                     f"{float(want).hex()} ({float(want)!r})")
        if not (is_double(L) and is_double(Up)):
            fail(f"{p}.g: guards must be binary64 numbers")
        for j in range(1, deg + 1):
            if code * L ** j < TWO ** -1022 and (j < deg or not last_underflows):
                fail(f"{p}: bound * lower_guard^{j} underflows")
            if code * Up ** j > TWO ** 1023:
                fail(f"{p}: bound * upper_guard^{j} may overflow")
        if L * L < TWO ** -1022 or Up * Up > TWO ** 1023:
            fail(f"{p}: the squared guards leave the normal range")
        for f in [g] + lemmas:
            if f.lower != L:
                fail(f"{f.name}.g: @lower_guard {f.lower} differs from {p}.g's {L}")
            check_model(f, L, Up)
            for e, v, t in f.tagged(f.hyps, "import"):
                key = t.split()[1]
                if key not in exports:
                    fail(f"{f.name}.g: @import {key} has no matching @export")
                    continue
                ee, ev = exports[key]
                src = key.split(":")[0]
                if files.get(src) is None or files[src].meta.get("lemma_of") != p:
                    fail(f"{f.name}.g: @import {key} comes from a file that is not a lemma of {p}")
                if ee != e or ev > v:
                    fail(f"{f.name}.g: @import |{e}| <= {v} is not implied by {key}: |{ee}| <= {ev}")
        print(f"{p}: E = {float(E)!r} ({float(E).hex()}), {constant} = {float(code).hex()} "
              f"= {float(code)!r}, guards [{float(L).hex()}, {float(Up).hex()}], "
              f"{len(lemmas)} lemma file(s)"
              + (", last rounding of the bound may underflow (charged)" if last_underflows else ""))
    if errors:
        print("\n".join("FAIL: " + e for e in errors))
        sys.exit(1)
    print("all filter constants match their proofs")


if __name__ == "__main__":
    main()
