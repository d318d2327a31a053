#!/usr/bin/env bash
# Compiles and runs the one-file consumer against an installed certimesh through pkg-config.
# usage: pkgconfig_consumer.sh <prefix> <source.cpp> <work dir> <c++ compiler> [extra flags...]
set -euo pipefail
prefix=$1 source=$2 work=$3 cxx=$4
shift 4
pcdir=$(dirname "$(find "$prefix" -name certimesh.pc -print -quit)")
[[ -f "$pcdir/certimesh.pc" ]] || { echo "certimesh.pc not installed under $prefix" >&2; exit 1; }
export PKG_CONFIG_PATH="$pcdir${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
pkg-config --exists --print-errors certimesh
echo "pkg-config --modversion certimesh: $(pkg-config --modversion certimesh)"
flags=$(pkg-config --cflags --libs certimesh)
echo "pkg-config --cflags --libs certimesh: $flags"
# The static form must name GMP (Requires.private).
static_flags=$(pkg-config --static --libs certimesh)
[[ " $static_flags " == *" -lgmp "* ]] || { echo "pkg-config --static lacks -lgmp: $static_flags" >&2; exit 1; }
mkdir -p "$work"
# shellcheck disable=SC2086  # the pkg-config flags are meant to split
"$cxx" -std=c++20 "$@" "$source" $flags -o "$work/pkgconfig_consumer"
"$work/pkgconfig_consumer"
