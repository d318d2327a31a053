#!/usr/bin/env bash
# The main job: build certimesh (Release, into build/) and run the CLI. With no arguments it
# runs the built-in demo (`certimesh demo`); any arguments are passed to certimesh instead,
# e.g. `scripts/run.sh predicates --mode exact < queries.txt`.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

bash scripts/install-deps.sh
jobs=${CERTIMESH_JOBS:-$(nproc)}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs" --target certimesh >/dev/null
if (($# == 0)); then
  exec build/bin/certimesh demo
fi
exec build/bin/certimesh "$@"
