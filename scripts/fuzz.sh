#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/) with clang, ASan and UBSan into build-fuzz/ and runs
# each for SECONDS (default 60) over a copy of its seed corpus, FUZZ_JOBS targets at a time
# (default: the number of cores). Exits non-zero if any target finds a crash, a leak, a hang
# or undefined behaviour; the input that did it is kept in build-fuzz/artifacts/TARGET/.
# docs/FUZZING.md. FUZZ_TARGETS="fuzz_png fuzz_glb" runs only those.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
bash scripts/setup.sh --sanitizers
build_dir=build-fuzz
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-16 -DPATINA_FUZZ=ON \
  -DPATINA_BUILD_TESTS=OFF >/dev/null
targets=(${FUZZ_TARGETS:-fuzz_material fuzz_scene fuzz_png fuzz_gltf fuzz_glb fuzz_hdr fuzz_exr})
cmake --build "$build_dir" -j"$(nproc)" --target "${targets[@]}"

# The working corpus lives in the build folder: what the fuzzer adds never reaches the tree.
run_target() {
  local target=$1 name=${1#fuzz_}
  local corpus="$build_dir/corpus/$name" artifacts="$build_dir/artifacts/$name" dict="$build_dir/$name.dict"
  mkdir -p "$corpus" "$artifacts"
  cp -n tests/fuzz/corpus/"$name"/* "$corpus"/
  case $name in
    material | scene) cat tests/fuzz/json.dict >"$dict" ;;
    png) cat tests/fuzz/png.dict tests/fuzz/json.dict >"$dict" ;;
    gltf | glb) cat tests/fuzz/gltf.dict tests/fuzz/json.dict >"$dict" ;;
    # Binary formats: the seeds hold their tokens, and libFuzzer picks up the ones the readers
    # compare against.
    *) dict= ;;
  esac
  # -timeout: one input taking 10 s is a hang. Sanitizer reports end the run (halt_on_error).
  "$build_dir/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    ${dict:+-dict="$dict"} -artifact_prefix="$artifacts/" -print_final_stats=1 "$corpus" \
    >"$build_dir/$target.log" 2>&1
}

export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-16/bin/llvm-symbolizer}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
jobs=${FUZZ_JOBS:-$(nproc)}
declare -A status
pending=("${targets[@]}")
while [ ${#pending[@]} -gt 0 ]; do
  batch=("${pending[@]:0:jobs}")
  pending=("${pending[@]:jobs}")
  declare -A pids=()
  for target in "${batch[@]}"; do
    run_target "$target" &
    pids[$target]=$!
  done
  for target in "${batch[@]}"; do
    if wait "${pids[$target]}"; then status[$target]=0; else status[$target]=$?; fi
  done
done

# One line per target from libFuzzer's final line ("#RUNS DONE cov: C ft: F corp: N/S ...").
failed=0
for target in "${targets[@]}"; do
  log="$build_dir/$target.log"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  done_line=$(grep -E '^#[0-9]+.*(DONE|cov:)' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$done_line")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$done_line")
  corp=$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<<"$done_line")
  if [ "${status[$target]}" -eq 0 ]; then
    printf 'fuzz: %-14s clean  %ss  %s runs  cov %s  ft %s  corpus %s\n' \
      "$target" "$seconds" "${runs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}"
  else
    failed=1
    printf 'fuzz: %-14s FAILED (exit %s)  %s runs; log %s; input in %s\n' "$target" \
      "${status[$target]}" "${runs:-?}" "$log" "$build_dir/artifacts/${target#fuzz_}/"
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 | sed 's/^/      /' || true
  fi
done
exit $failed
