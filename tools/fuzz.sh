#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz/: the OBJ/MTL loader, the scene file, the glTF loader) with
# clang, AddressSanitizer and UBSan, and runs each for FUZZ_SECONDS (default 60) from its seed corpus.
# Any crash is saved as crash-* in build-fuzz/ and fails the run; turn it into a regression test under
# tests/scene/ before fixing it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFP_FUZZ=ON >/dev/null
cmake --build build-fuzz --target obj_fuzz scene_fuzz gltf_fuzz -j 2
for target in obj scene gltf; do
    mkdir -p build-fuzz/corpus_$target
    echo "fuzzing the $target loader for ${seconds}s"
    dict=()  # a dictionary of the format's words, if the harness has one (tests/fuzz/gltf.dict)
    [ -f tests/fuzz/$target.dict ] && dict=(-dict=../tests/fuzz/$target.dict)
    (cd build-fuzz && ./${target}_fuzz -max_total_time="$seconds" -max_len=4096 -timeout=10 "${dict[@]}" \
        corpus_$target ../tests/fuzz/corpus/$target 2>&1 | tail -n 3)
done
echo "fuzz: no crashes"
