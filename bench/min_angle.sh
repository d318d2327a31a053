#!/bin/sh
# --min-angle beside the size-only Delaunay refinement, the advancing front and Gmsh, on the
# unit square and on NACA 0012 in a box (bench/RESULTS.md, "min-angle"). certimesh: the stage
# clock's sum (wall; meshing only) and the process's user+sys CPU (meshing, certificate, writing);
# Gmsh: its own "Done meshing 2D" CPU time. Usage:
#   bench/min_angle.sh BUILD_DIR H_SQUARE H_AIRFOIL
set -eu
build=${1:-build}; hs=${2:-0.005}; ha=${3:-0.01}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3
cm="$build/bin/certimesh"
$py "$here/min_angle_stats.py" domain square_sized "$work/square.poly" "$work/square.geo" "$hs"
$py "$here/min_angle_stats.py" domain naca0012_box "$work/naca.poly" "$work/naca.geo" "$ha"
run() {  # name domain h options...
  name=$1; dom=$2; h=$3; shift 3
  out="$work/$name.vtu"
  status=0
  /usr/bin/time -f 'cpu %U %S' -o "$work/cpu" $cm mesh "$work/$dom.poly" -o "$out" --size "$h" --quiet "$@" \
    > "$work/log" 2>&1 || status=$?
  t=$(sed -n 's/^time: \([0-9.]*\) s.*/\1/p' "$work/log")
  cpu=$(awk '/^cpu/ {print $2 + $3}' "$work/cpu")
  printf '%-58s exit %s  stages %6s s wall, process %6s s CPU  ' "$name $*" "$status" "$t" "$cpu"
  $py "$here/min_angle_stats.py" angles "$out"
}
gmsh_run() {  # name domain h
  name=$1; dom=$2; h=$3
  gmsh "$work/$dom.geo" -2 -nt 1 -clmax "$h" -o "$work/$name.msh" > "$work/log" 2>&1
  t=$(sed -n 's/.*Done meshing 2D (Wall \([0-9.e-]*\)s, CPU \([0-9.e-]*\)s).*/\2/p' "$work/log" | tail -1 | tr -d '\r\n')
  printf '%-58s exit 0  meshing %6s s CPU  ' "$name (gmsh -2)" "$t"; $py "$here/min_angle_stats.py" angles "$work/$name.msh"
}
for dom_h in "square $hs" "naca $ha"; do
  set -- $dom_h; dom=$1; h=$2
  echo "== $dom, size $h"
  run "$dom-delaunay" "$dom" "$h" --algorithm delaunay --no-improve
  run "$dom-delaunay+improve" "$dom" "$h" --algorithm delaunay
  run "$dom-delaunay-q20.7" "$dom" "$h" --algorithm delaunay --min-angle 20.7
  run "$dom-delaunay-q30" "$dom" "$h" --algorithm delaunay --min-angle 30
  run "$dom-delaunay-q33" "$dom" "$h" --algorithm delaunay --min-angle 33
  run "$dom-front" "$dom" "$h"
  run "$dom-front-q20.7" "$dom" "$h" --min-angle 20.7
  run "$dom-front-q30" "$dom" "$h" --min-angle 30
  gmsh_run "$dom-gmsh" "$dom" "$h"
done
