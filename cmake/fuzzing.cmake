# Fuzzing builds (docs/fuzzing.md). Each is a build folder of its own, configured by scripts/fuzz-build:
#   ANISOCERT_FUZZ_ENGINE=libfuzzer  clang: every library instrumented (-fsanitize=fuzzer-no-link),
#                                    each harness linked with libFuzzer as fuzz_<name>
#   ANISOCERT_FUZZ_ENGINE=afl        afl-clang-fast++: AFL++ instruments everything, each harness
#                                    linked with AFL++'s libFuzzer driver as fuzz_<name>
#   ANISOCERT_FUZZ_ENGINE=external   OSS-Fuzz / ClusterFuzzLite: the builder's CXXFLAGS instrument,
#                                    each harness links ANISOCERT_FUZZ_LINK ($LIB_FUZZING_ENGINE)
#   ANISOCERT_SANITIZE=address,undefined   sanitizers on every target, errors fatal
#   ANISOCERT_COVERAGE=ON            clang source-based coverage of the replay drivers (llvm-cov)
# Any of them builds fuzz/ without the tests; with the tests, fuzz/ builds the replay drivers only.
set(ANISOCERT_FUZZ_ENGINE "" CACHE STRING "libfuzzer or afl: build each fuzz/ harness for that engine (clang)")
set_property(CACHE ANISOCERT_FUZZ_ENGINE PROPERTY STRINGS "" libfuzzer afl external)
set(ANISOCERT_FUZZ_LINK "-fsanitize=fuzzer" CACHE STRING "how a harness links its engine (OSS-Fuzz: $LIB_FUZZING_ENGINE)")
set(ANISOCERT_SANITIZE "" CACHE STRING "sanitizers for every target, e.g. address,undefined")
option(ANISOCERT_COVERAGE "clang source-based coverage (-fprofile-instr-generate -fcoverage-mapping)" OFF)

set(anisocert_FUZZ OFF)
if(ANISOCERT_FUZZ_ENGINE OR ANISOCERT_SANITIZE OR ANISOCERT_COVERAGE)
  set(anisocert_FUZZ ON)
endif()
if(ANISOCERT_FUZZ_ENGINE AND NOT ANISOCERT_FUZZ_ENGINE MATCHES "^(libfuzzer|afl|external)$")
  message(FATAL_ERROR "ANISOCERT_FUZZ_ENGINE: \"${ANISOCERT_FUZZ_ENGINE}\" is not libfuzzer, afl or external")
endif()
if(ANISOCERT_FUZZ_ENGINE MATCHES "^(libfuzzer|afl)$" AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "ANISOCERT_FUZZ_ENGINE=${ANISOCERT_FUZZ_ENGINE} needs clang (CXX=clang++-14, or afl-clang-fast++), not ${CMAKE_CXX_COMPILER_ID}")
endif()
if(ANISOCERT_SANITIZE)
  add_compile_options(-fsanitize=${ANISOCERT_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${ANISOCERT_SANITIZE})
endif()
if(ANISOCERT_FUZZ_ENGINE STREQUAL "libfuzzer")
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
if(ANISOCERT_COVERAGE)
  add_compile_options(-fprofile-instr-generate -fcoverage-mapping)
  add_link_options(-fprofile-instr-generate)
endif()
