#!/usr/bin/env bash
# refine --from (issue 41) side by side: from bamg's mesh of the default shock field (the issue's
# headline case, made by scripts/validate) and FreeFem's kept L-shape (tests/peers/fixtures), each
# with BWY, BWY --off-centres, BWY --coarsen, both, the two with --relocate, and with --collapse
# too, LS and star, and
# FreeFem's and bamg's meshes of the rotated constant metric (tests/peers/fixtures) with star, one
# run each: wall time, vertices (×
# the input's), the certifier's unit-edge share and smallest angle after, and the certificate:
# the oracle's for bwy and ls (the dual of the exact D|Ω of the output's vertices), the
# certifier's local uniformity for star.
# Run: bash bench/refine_from.sh (needs freefem++ for bamg: apt-get install freefem++; figures in
# docs/bench.md and docs/validation.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/bin/anisocert
[ -x "$bin" ] || scripts/build program
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scripts/validate --peer bamg --out "$work/bamg" >/dev/null || [ -f "$work/bamg/mesh.msh" ] || { echo "refine_from: bamg's mesh failed" >&2; exit 2; }

row() {  # name mesh field-args… -- refine-args…
  local name=$1 mesh=$2; shift 2
  local field=() ; while [ "$1" != "--" ]; do field+=("$1"); shift; done; shift
  local t0 t1 out
  t0=$(date +%s.%N)
  out=$("$bin" refine --quiet --from "$mesh" "${field[@]}" "$@" -o "$work/out.json" 2>&1 || true)
  t1=$(date +%s.%N)
  local before after ratio cert
  before=$(sed -n 's/^  before: \([0-9]*\) vertices.*unit edges \([0-9.]*%\).*smallest angle \([0-9.]*°\).*/\1 vertices, \2 unit, \3/p' <<<"$out")
  after=$(sed -n 's/^  after: *\([0-9]*\) vertices.*unit edges \([0-9.]*%\).*smallest angle \([0-9.]*°\).*/\1 vertices, \2 unit, \3/p' <<<"$out")
  ratio=$(grep -oE '\([0-9.]+×\)' <<<"$out" || true)
  cert=$(grep -qE '^  certified' <<<"$out" && echo certified || echo "NOT certified")
  printf '%-34s %-26s %6.1f s  %s %s  %s  (before: %s)\n' "$name" "$*" "$(echo "$t1 - $t0" | bc)" "$after" "$ratio" "$cert" "$before"
}

for case in "bamg shock (default)|$work/bamg/mesh.msh|--field shock" \
            "freefem L-shape shock h=0.1|tests/peers/fixtures/freefem-lshape-shock-coarse.msh|--field shock --param h=0.1"; do
  IFS='|' read -r name mesh field <<<"$case"
  # shellcheck disable=SC2086
  for algo in "--algo bwy" "--algo bwy --off-centres" "--algo bwy --coarsen" "--algo bwy --off-centres --coarsen" "--algo bwy --off-centres --coarsen --relocate" "--algo bwy --off-centres --coarsen --collapse --relocate" "--algo ls" "--algo star"; do row "$name" "$mesh" $field -- $algo; done
done
rotated="--field constant --param m11=1258.0800065610586 --param m12=-3181.7986679483697 --param m22=8841.9199934389417"
for peer in freefem bamg; do
  # shellcheck disable=SC2086
  row "$peer rotated constant 20°" "tests/peers/fixtures/$peer-constant-20deg.msh" $rotated -- --algo star
done
