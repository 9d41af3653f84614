#!/bin/bash -eu
# The OSS-Fuzz / ClusterFuzzLite build (docs/fuzzing.md): the builder gives $CC, $CXX, $CFLAGS,
# $CXXFLAGS (sanitizer and coverage instrumentation), $LIB_FUZZING_ENGINE, $SRC and $OUT. Each
# harness of fuzz/limits becomes $OUT/fuzz_<harness>, with its seed corpus
# (fuzz_<harness>_seed_corpus.zip), its dictionary (fuzz_<harness>.dict) and its limits
# (fuzz_<harness>.options: max_len and timeout).
cd "$SRC/anisocert"
cmake -S . -B build-oss -G Ninja -DCMAKE_BUILD_TYPE=Release -DANISOCERT_TESTS=OFF -DANISOCERT_FUZZ_ENGINE=external \
  -DANISOCERT_FUZZ_LINK="$LIB_FUZZING_ENGINE"
while read -r harness max_len timeout; do
  [[ -z "$harness" || "$harness" == \#* ]] && continue
  cmake --build build-oss --target "fuzz_$harness" || { echo "build.sh: fuzz_$harness not built (its libraries missing?)"; continue; }
  cp "build-oss/bin/fuzz_$harness" "$OUT/"
  (cd "fuzz/corpora/$harness" && zip -q -r "$OUT/fuzz_${harness}_seed_corpus.zip" .)
  [ -f "fuzz/dictionaries/$harness.dict" ] && cp "fuzz/dictionaries/$harness.dict" "$OUT/fuzz_$harness.dict"
  printf '[libfuzzer]\nmax_len = %s\ntimeout = %s\n' "$max_len" "$timeout" >"$OUT/fuzz_$harness.options"
done <fuzz/limits
