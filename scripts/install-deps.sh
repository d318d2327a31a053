#!/usr/bin/env bash
# Installs the Debian 12 packages certimesh needs, when any is missing.
# Idempotent and silent when everything is present; non-interactive; runs apt-get as root,
# or through sudo when not root. Exit status: 0 when all packages are (now) installed.
set -euo pipefail

packages=(
  build-essential cmake git pkg-config        # toolchain
  libgmp-dev libmpfr-dev libboost-dev         # exact arithmetic (library, oracles)
  libcgal-dev                                 # oracle in tests, peer in benchmarks
  librapidcheck-dev libgtest-dev              # test suite
  libbenchmark-dev                            # benchmarks
  gappa libcoq-gappa coq                      # filter-bound proofs
  clang libclang-rt-14-dev binutils           # fuzzers, sanitizer runtimes, object-code scan
  lld                                         # the suite links its ~100 executables with it
  ccache                                      # developers' builds (CMAKE_CXX_COMPILER_LAUNCHER=ccache)
  python3 python3-meshio python3-numpy        # CLI and format tests (/usr/bin/python3)
  time                                        # /usr/bin/time -v in the constant-memory test
  gmsh                                        # interop: Gmsh must read what certimesh writes
  tetgen                                      # peer: the 3D .poly/.smesh domains, certified
  libssl-dev                                  # SHA-256 of the mesh in the certificate
  zlib1g-dev                                  # compressed .vtu (meshio's default) in io
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null || true)
  [[ "$status" == ii* ]] || missing+=("$p")
done
((${#missing[@]} == 0)) && exit 0

echo "install-deps: installing ${missing[*]}" >&2
if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install-deps: error: missing packages (${missing[*]}) and neither root nor sudo" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
