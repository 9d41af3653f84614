#!/usr/bin/env bash
# The 3D star refiner beside two isotropic tetrahedral meshers on the unit cube at edge size 0.1
# (issue 40: "compare with other meshers' runs where a size field applies"; the field 100 I is
# the one where an isotropic size field says the same): `anisocert refine --algo star`, Gmsh 3D
# (Delaunay, CharacteristicLength 0.1) and TetGen (-pq1.414, largest volume √2/12 · 0.1³, a unit
# tetrahedron's), each timed (wall clock, one run), each mesh certified by the same command for
# 100 I with ρ₀ = 3, γ₀ = 1.5. CGAL Mesh_3 is not here: the project's CGAL peer meshes the unit
# ball (an implicit domain), which the refiner, taking polyhedra, does not.
# Run: bash bench/star3_peers.sh (needs gmsh and tetgen: apt-get install gmsh tetgen; figures in
# docs/bench.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/anisocert
[ -x "$bin" ] || scripts/build anisocert
for tool in gmsh tetgen; do command -v "$tool" >/dev/null || { echo "star3_peers: $tool is not installed (apt-get install $tool)" >&2; exit 2; }; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field=(--field constant --param m11=100 --param m22=100 --param m33=100)

seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >"$work/log" 2>&1; t1=$(date +%s.%N); printf '%.3f' "$(echo "$t1 - $t0" | bc)"; }
certify() {  # mesh → the certificate's verdict lines
  { "$bin" certify "$1" "${field[@]}" --rho0 3 --gamma0 1.5 --threads 1 2>&1 || true; } |
    grep -E "^[^ ].*vertices, |^  (valid|locally uniform|radius-edge|edge lengths|mean-ratio|dihedral)|^certified|^not certified" |
    sed -E 's/ \(every [^)]*\)//; s/\(tetrahedra on [^)]*\)//' | cut -c1-160
}

echo "== anisocert refine --algo star (the run's own time; it certifies its mesh after)"
"$bin" refine --algo star --domain cube "${field[@]}" --quiet --threads 1 -o "$work/star.mesh" | grep -E "star refiner \(3D\)"
certify "$work/star.mesh"

echo "== gmsh -3"
printf 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\nMesh.CharacteristicLengthMin = 0.1;\nMesh.CharacteristicLengthMax = 0.1;\n' >"$work/cube.geo"
echo "  $(seconds gmsh -3 "$work/cube.geo" -o "$work/gmsh.msh" -format msh41) s"
certify "$work/gmsh.msh"

echo "== tetgen -pq1.414a0.0001178"
{
  echo "8 3 0 0"
  for k in 0 1 2 3 4 5 6 7; do echo "$((k + 1)) $((k & 1)) $(((k >> 1) & 1)) $(((k >> 2) & 1))"; done
  echo "6 0"
  for f in "1 3 4 2" "5 6 8 7" "1 2 6 5" "3 7 8 4" "1 5 7 3" "2 4 8 6"; do printf '1\n4 %s\n' "$f"; done
  echo "0"
  echo "0"
} >"$work/cube.poly"
echo "  $(seconds tetgen -pq1.414a0.0001178 "$work/cube.poly") s"
certify "$work/cube.1.ele"
