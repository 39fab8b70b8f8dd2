#!/bin/sh
# Fuzzes every parser of user input with libFuzzer under AddressSanitizer + UndefinedBehaviorSanitizer
# (docs/reliability.md, "Fuzzing").
#
#   scripts/fuzz.sh [MINUTES] [TARGET...]     MINUTES in total (default 10), shared by the targets (default: all)
#
# Builds build/fuzz with clang (RBCSTAB_FUZZ=ON; Debian: apt-get install clang, whose libclang-rt-14-dev holds
# libFuzzer), runs each target for its share of the time on one core (-jobs is not used: the machine is shared),
# starting from fuzz/corpus/<target>/, then merges the inputs that reach new coverage into that folder
# (set RBCSTAB_FUZZ_MERGE=0 to keep them in build/fuzz/found/<target>/ only). A crash, a sanitizer report or a
# broken invariant stops that target and leaves the input in build/fuzz/artifacts/; replay it with
# build/release/fuzz/fuzz_<target>_replay FILE and, once fixed, keep it in fuzz/corpus/<target>/regressions/.
# Each target's libFuzzer log (executions, exec/s, cov, ft) is build/fuzz/logs/<target>.log.
set -eu
minutes=${1:-10}
[ $# -gt 0 ] && shift
root=$(cd "$(dirname "$0")/.." && pwd)
build=${RBCSTAB_FUZZ_BUILD:-$root/build/fuzz}
cxx=${CXX:-clang++}
targets=${*:-"scene_toml mode_list cli_lists cli_args branch_file journal merge"}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" \
  -DRBCSTAB_FUZZ=ON -DRBCSTAB_BUILD_TESTS=OFF -DRBCSTAB_BUILD_BENCHMARKS=OFF > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log"; exit 1; }
fuzzers=""
for t in $targets; do fuzzers="$fuzzers fuzz_$t"; done
cmake --build "$build" -j2 --target $fuzzers

set -- $targets
seconds=$(( minutes * 60 / $# ))
[ "$seconds" -ge 1 ] || seconds=1
mkdir -p "$build/logs" "$build/artifacts"
status=0
for t in $targets; do
  found="$build/found/$t"
  mkdir -p "$found"
  echo "fuzz.sh: $t for ${seconds}s"
  if ! "$build/fuzz/bin/fuzz_$t" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$build/artifacts/$t-" "$found" "$root/fuzz/corpus/$t" > "$build/logs/$t.log" 2>&1; then
    echo "fuzz.sh: $t FAILED (see $build/logs/$t.log and $build/artifacts/)"
    status=1
  fi
  grep -E "^#[0-9]+.*(DONE|pulse)|stat::number_of_executed_units|stat::average_exec_per_sec" "$build/logs/$t.log" | tail -3
  if [ "${RBCSTAB_FUZZ_MERGE:-1}" = 1 ]; then
    "$build/fuzz/bin/fuzz_$t" -merge=1 "$root/fuzz/corpus/$t" "$found" > "$build/logs/$t.merge.log" 2>&1 ||
      echo "fuzz.sh: merging $t's new inputs failed (see $build/logs/$t.merge.log)"
  fi
done
exit $status
