#!/usr/bin/env python3
"""Checks a certificate JSON written by `certimesh check --certificate`, without assuming its
exact layout: it must parse, record the element count under a key naming elements, a verdict
(a key naming "valid" or "verdict") that matches the exit code, the defect's name when
invalid, a SHA-256 hex digest and a version string.

usage: check_certificate_json.py FILE EXIT_CODE DEFECT[|DEFECT...] ELEMENTS
"""
import json
import re
import sys


def walk(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from walk(v, f"{path}.{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from walk(v, f"{path}[{i}]")
    else:
        yield path.lower(), node


def main():
    path, code, defects, elements = sys.argv[1], int(sys.argv[2]), sys.argv[3].split("|"), int(sys.argv[4])
    with open(path) as f:
        doc = json.load(f)
    leaves = list(walk(doc))
    problems = []
    if not any("element" in k and type(v) is int and v == elements for k, v in leaves):
        problems.append(f"no element count {elements}")
    verdicts = [v for k, v in leaves if k.endswith("valid") or "verdict" in k]
    want_valid = code == 0
    if not any(v is want_valid or (isinstance(v, str) and v.lower() == ("valid" if want_valid else "invalid"))
               for v in verdicts):
        problems.append(f"no verdict saying {'valid' if want_valid else 'invalid'} (found {verdicts})")
    if not want_valid and not any(isinstance(v, str) and v in defects for _, v in leaves):
        problems.append(f"defect {'|'.join(defects)} not recorded")
    if not any(isinstance(v, str) and re.fullmatch(r"[0-9a-f]{64}", v) for _, v in leaves):
        problems.append("no SHA-256 digest")
    if not any("version" in k and isinstance(v, str) and v for k, v in leaves):
        problems.append("no version")
    if problems:
        print(f"{path}: " + "; ".join(problems))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
