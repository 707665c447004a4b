#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/) with clang, ASan and UBSan in build-asan/, the tree
# scripts/sanitize.sh builds the suite in (scripts/sanitized_tree.sh), and runs them over a copy
# of their seed corpora, FUZZ_JOBS at a time (default: the number of cores), for SECONDS each on
# average (default 60): each target's share of the time below. Exits non-zero if any target
# finds a crash, a leak, a hang or undefined behaviour; the input that did it is kept in
# build-asan/artifacts/TARGET/. docs/FUZZING.md. FUZZ_TARGETS="fuzz_png fuzz_glb" runs only those.
# shellcheck disable=SC2317  # the functions below run through `stage`
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
# shellcheck source=scripts/stages.sh
source scripts/stages.sh
trap stage_summary EXIT
# shellcheck source=scripts/sanitized_tree.sh
source scripts/sanitized_tree.sh
build_dir=$sanitized_dir
stage "fuzz setup" bash scripts/setup.sh --sanitizers
stage "fuzz configure" configure_sanitized_tree
read -ra targets <<<"${FUZZ_TARGETS:-fuzz_gltf fuzz_glb fuzz_material fuzz_scene fuzz_png fuzz_exr fuzz_hdr}"
stage "fuzz build" cmake --build "$build_dir" -j"$(nproc)" --target "${targets[@]}"

# Each target's share of SECONDS x the number of targets, for the time that finds bugs. In the
# second half of a 60 s run from the seeds (a CI run on the 2-core machine) the glTF targets found
# about 150 new edges each, of 5,600-5,800, at 200-300 inputs a second; the image headers' walks
# 16 and 4, of 330 and 620, at 3,500-4,500 a second. The longest go first, so the jobs end
# together.
declare -A share=([fuzz_gltf]=1.5 [fuzz_glb]=1.5 [fuzz_material]=1 [fuzz_scene]=1 [fuzz_png]=1
  [fuzz_exr]=0.5 [fuzz_hdr]=0.5)

# The working corpus lives in the build folder: what the fuzzer adds never reaches the tree.
run_target() {
  local target=$1 seconds=$2 name=${1#fuzz_}
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

# One pool of FUZZ_JOBS: a target starts as soon as one ends.
run_targets() {
  local jobs=${FUZZ_JOBS:-$(nproc)} target pid
  declare -A running=()
  for target in "${targets[@]}"; do
    if [ ${#running[@]} -ge "$jobs" ]; then
      wait_one running
    fi
    run_target "$target" "${time_of[$target]}" &
    running[$!]=$target
  done
  while [ ${#running[@]} -gt 0 ]; do
    wait_one running
  done
}
wait_one() {
  local -n jobs_running=$1
  local pid code=0
  wait -n -p pid "${!jobs_running[@]}" || code=$?
  status[${jobs_running[$pid]}]=$code
  unset "jobs_running[$pid]"
}
declare -A status time_of
for target in "${targets[@]}"; do
  time_of[$target]=$(awk -v s="$seconds" -v f="${share[$target]:-1}" 'BEGIN { printf "%d", s * f + 0.5 }')
done
stage "fuzz runs" run_targets

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
      "$target" "${time_of[$target]}" "${runs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}"
  else
    failed=1
    printf 'fuzz: %-14s FAILED (exit %s)  %s runs; log %s; input in %s\n' "$target" \
      "${status[$target]}" "${runs:-?}" "$log" "$build_dir/artifacts/${target#fuzz_}/"
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 | sed 's/^/      /' || true
  fi
done
exit $failed
