#!/usr/bin/env bash
# scripts/check_layers must fail on forbidden includes and pass on allowed ones: a tree of a few
# files is built in a temporary folder, one forbidden include at a time, and the check is run on
# it (each case names the rule it exercises). Usage: check_layers_test.sh PROJECT_ROOT
set -u
check="$1/scripts/check_layers"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

tree() {  # a clean tree with one file per layer, each including what it may
  rm -rf "$tmp/t" && mkdir -p "$tmp/t"/{numbers,theory,predicates,geometry,fields,oracle/algebraic,oracle/diagram,refiners/common,refiners/star,io,cli,api}
  echo '#include "numbers/rational.hpp"' > "$tmp/t/theory/a.hpp"
  echo '#include "numbers/sign.hpp"' > "$tmp/t/predicates/a.hpp"
  echo '#include "predicates/a.hpp"' > "$tmp/t/geometry/a.hpp"
  echo '#include "geometry/a.hpp"' > "$tmp/t/fields/a.hpp"
  echo '#include "geometry/a.hpp"' > "$tmp/t/oracle/diagram/a.hpp"
  echo '#include "oracle/algebraic/b.hpp"' >> "$tmp/t/oracle/diagram/a.hpp"
  echo '#include "refiners/common/a.hpp"' > "$tmp/t/refiners/star/a.cpp"
  echo '#include "fields/a.hpp"' > "$tmp/t/refiners/common/a.hpp"
  echo '#include "refiners/star/a.hpp"' > "$tmp/t/refiners/registry.cpp"
  echo '#include "oracle/diagram/a.hpp"' > "$tmp/t/io/a.cpp"
  echo '#include "refiners/registry.hpp"' > "$tmp/t/cli/a.cpp"
  echo '#include "io/a.hpp"' >> "$tmp/t/cli/a.cpp"
  echo '#include "io/reports/a.hpp"' > "$tmp/t/api/a.cpp"
  echo '#include "oracle/certify/a.hpp"' >> "$tmp/t/api/a.cpp"
}

expect() {  # expect WHAT EXIT FILE INCLUDE [MESSAGE-FRAGMENT]
  local what=$1 want=$2 file=$3 include=$4 fragment=${5:-}
  tree
  [ -n "$file" ] && echo "#include \"$include\"" >> "$tmp/t/$file"
  out=$(bash "$check" "$tmp/t" 2>&1); got=$?
  if [ "$got" != "$want" ] || { [ -n "$fragment" ] && ! grep -qF -- "$fragment" <<<"$out"; }; then
    echo "FAIL: $what: exit $got (want $want); output: $out"
    failures=$((failures + 1))
  else
    echo "ok: $what"
  fi
}

expect "a clean tree passes" 0 "" ""
expect "refiners/ may not include the oracle" 1 refiners/star/a.cpp oracle/diagram/a.hpp "refiners/ may not include oracle/"
expect "refiners/ may not include io/" 1 refiners/common/a.hpp io/a.hpp "refiners/ may not include io/"
expect "geometry/ may not include fields/ (above it)" 1 geometry/a.hpp fields/a.hpp "geometry/ may not include fields/"
expect "fields/ may not include refiners/" 1 fields/a.hpp refiners/common/a.hpp "fields/ may not include refiners/"
expect "predicates/ may not include theory/" 1 predicates/a.hpp theory/a.hpp "predicates/ may not include theory/"
expect "numbers/ includes nothing above it" 1 numbers/a.hpp predicates/a.hpp "numbers/ may not include predicates/"
expect "io/ may not include refiners/" 1 io/a.cpp refiners/registry.hpp "io/ may not include refiners/"
expect "the oracle may not include cli/" 1 oracle/diagram/a.hpp cli/a.hpp "oracle/ may not include cli/"
expect "a refiner may not include another refiner" 1 refiners/star/a.cpp refiners/ls/a.hpp "refiners/star may not include refiners/ls/"
expect "refiners/common/ may not include a refiner" 1 refiners/common/a.hpp refiners/star/a.hpp "refiners/common may not include refiners/star/"
expect "exact algebraic points may not include the diagram" 1 oracle/algebraic/b.hpp oracle/diagram/a.hpp "oracle/algebraic may not include oracle/diagram/"
expect "relative includes are refused" 1 geometry/a.hpp ../fields/a.hpp "relative include"
expect "cli/ may include every layer" 0 cli/a.cpp oracle/certify/c.hpp
expect "a refiner whose name has digits is a refiner too" 1 refiners/star/a.cpp refiners/ls2/a.hpp "refiners/star may not include refiners/ls2/"
expect "refiners/common/ may not include the registry (every refiner)" 1 refiners/common/a.hpp refiners/registry.hpp "refiners/common may not include refiners/"
expect "api/ may include fields/" 0 api/a.cpp fields/a.hpp
expect "api/ may not include refiners/" 1 api/a.cpp refiners/registry.hpp "api/ may not include refiners/"
expect "api/ may not include cli/" 1 api/a.cpp cli/a.hpp "api/ may not include cli/"
expect "cli/ does not use api/" 1 cli/a.cpp api/anisocert.hpp "cli/ may not include api/"
expect "an .ipp file is checked too" 1 refiners/star/a.ipp oracle/diagram/a.hpp "refiners/ may not include oracle/"

angled() {  # an angle-bracket include of a project layer is a project include
  tree
  echo '#include <oracle/diagram/a.hpp>' >> "$tmp/t/refiners/star/a.cpp"
  echo '#include <vector>' >> "$tmp/t/refiners/star/a.cpp"
  echo '#include <numbers>' >> "$tmp/t/refiners/star/a.cpp"   # C++20's, not the layer
  out=$(bash "$check" "$tmp/t" 2>&1); got=$?
  if [ "$got" = 1 ] && grep -qF "refiners/ may not include oracle/" <<<"$out" && ! grep -qF "vector" <<<"$out" &&
     ! grep -qF "numbers" <<<"$out"; then
    echo "ok: angle-bracket includes of a layer are checked, system headers are not"
  else
    echo "FAIL: angle-bracket includes: exit $got; output: $out"
    failures=$((failures + 1))
  fi
}
angled

links() {  # a layer's CMakeLists.txt may link only the libraries of the layers it may include
  tree
  printf 'add_library(anisocert_refiners STATIC a.cpp)\ntarget_link_libraries(anisocert_refiners PUBLIC anisocert_geometry\n  anisocert_oracle)\n' > "$tmp/t/refiners/CMakeLists.txt"
  out=$(bash "$check" "$tmp/t" 2>&1); got=$?
  if [ "$got" = 1 ] && grep -qF "refiners/CMakeLists.txt:3: refiners/ may not link anisocert_oracle" <<<"$out"; then
    echo "ok: a forbidden link is caught, also on a continuation line"
  else
    echo "FAIL: links: exit $got; output: $out"
    failures=$((failures + 1))
  fi
}
links

exit $((failures > 0))
