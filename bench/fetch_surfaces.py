#!/usr/bin/env python3
"""Fetch the big surfaces of bench/data/surfaces/SOURCES.md into a cache and check their SHA-256.

Every row of the table in SOURCES.md names a file, where it comes from
(`owner/repo@commit:path`) and its SHA-256. A file that is in bench/data/surfaces/ itself is not
fetched. The others are taken, in this order, from
  1. the cache (bench/data/surfaces/cache/ or --cache DIR) when it holds the right bytes;
  2. a local copy: Debian's occt-misc installs OpenCASCADE's samples in
     /usr/share/opencascade/data/stl/ (the OCCT rows);
  3. https://raw.githubusercontent.com/OWNER/REPO/COMMIT/PATH.
A file whose SHA-256 differs from the table's is not kept (exit status 1, the reason printed).

Standard library only.
Usage:
  python3 bench/fetch_surfaces.py [--cache DIR] [--all] [--only NAME ...]
  (--all: the dropped rows too, e.g. to see why the harness refuses them)
"""

import argparse
import hashlib
import os
import sys
import urllib.error
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data", "surfaces")
LOCAL_COPIES = {"Open-Cascade-SAS/OCCT": "/usr/share/opencascade"}


def rows(path):
    """(file, where, sha256, status) of every table row of SOURCES.md."""
    found = []
    with open(path) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) >= 7 and cells[0].startswith("`"):
                found.append((cells[0].strip("`"), cells[3], cells[5].strip("`"), cells[6]))
    return found


def digest(data):
    return hashlib.sha256(data).hexdigest()


def origin(where):
    """'owner/repo@commit:path ...' -> (owner/repo, commit, path), or None."""
    head = where.split()[-1] if where.startswith("derived") else where.split()[0]
    if "@" not in head or ":" not in head:
        return None
    repo, rest = head.split("@", 1)
    commit, path = rest.split(":", 1)
    return repo, commit, path


def candidates(repo, commit, path):
    """Where the bytes may be had: (description, reader) pairs."""
    local = LOCAL_COPIES.get(repo)
    if local:
        yield local + "/" + path, lambda p=local + "/" + path: open(p, "rb").read()
    url = "https://raw.githubusercontent.com/%s/%s/%s" % (repo, commit, path)
    yield url, lambda: urllib.request.urlopen(url, timeout=60).read()


def fetch(name, where, sha256, cache):
    if os.path.exists(os.path.join(DATA, name)):
        return "in the repository"
    target = os.path.join(cache, name)
    if os.path.exists(target):
        with open(target, "rb") as f:
            if digest(f.read()) == sha256:
                return "cached"
    parsed = origin(where)
    if parsed is None:
        raise RuntimeError("no repository@commit:path in %r" % where)
    reasons = []
    for description, read in candidates(*parsed):
        try:
            data = read()
        except (OSError, urllib.error.URLError) as e:
            reasons.append("%s: %s" % (description, e))
            continue
        if sha256 and digest(data) != sha256:
            reasons.append("%s: SHA-256 %s, SOURCES.md says %s" % (description, digest(data), sha256))
            continue
        os.makedirs(cache, exist_ok=True)
        partial = target + ".part"
        with open(partial, "wb") as f:
            f.write(data)
        os.replace(partial, target)
        return "from " + description
    raise RuntimeError("; ".join(reasons))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cache", default=os.path.join(DATA, "cache"))
    parser.add_argument("--sources", default=os.path.join(DATA, "SOURCES.md"))
    parser.add_argument("--all", action="store_true", help="dropped rows too")
    parser.add_argument("--only", nargs="*")
    args = parser.parse_args()
    failed = 0
    for name, where, sha256, status in rows(args.sources):
        if not args.all and not status.startswith("kept"):
            continue
        if args.only and not any(o in name for o in args.only):
            continue
        try:
            print("%s: %s" % (name, fetch(name, where, sha256, args.cache)))
        except RuntimeError as e:
            failed += 1
            print("%s: not fetched: %s" % (name, e), file=sys.stderr)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
