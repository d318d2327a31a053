#!/usr/bin/env bash
# The main job: build certimesh (Release, into build/) and run the CLI. With no arguments it
# meshes the built-in default domain (a plate with two holes and a crack) and writes, into
# out/, the mesh (plate.vtu), its certificate (plate.certificate.json), a picture (plate.svg)
# and the domain (plate.poly, for `certimesh check out/plate.vtu --domain out/plate.poly`).
# Any arguments are passed to certimesh instead, e.g. `scripts/run.sh demo` or
# `scripts/run.sh predicates --mode exact < queries.txt`.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

bash scripts/install-deps.sh
jobs=${CERTIMESH_JOBS:-$(nproc)}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs" --target certimesh >/dev/null
if (($# == 0)); then
  mkdir -p out
  exec build/bin/certimesh mesh builtin:plate --size 0.05 -o out/plate.vtu \
    --certificate out/plate.certificate.json --svg out/plate.svg --save-domain out/plate.poly
fi
exec build/bin/certimesh "$@"
