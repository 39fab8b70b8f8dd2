#!/usr/bin/env bash
# Measures the build budget of docs/building.md from clean clones of the current commit, cold (ccache off):
#   1. `setup.sh run` from a fresh clone to the report written (packages already installed), and its first output;
#   2. `.ci/run` in a second fresh clone: full build (wall and compiler CPU), default suite, sanitized stage, total;
#   3. the incremental rebuild after touching one .cpp in src/, to a runnable CLI.
# Usage: scripts/build_budget.sh [WORK_DIR]   (default: a new folder under /tmp; about 35 min on 2 cores)
# Needs the packages of scripts/setup.sh (run it once first) and a committed tree: it measures HEAD, not edits.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${1:-$(mktemp -d /tmp/rbcstab-budget.XXXXXX)}"
mkdir -p "$work"
export CCACHE_DISABLE=1  # every figure cold
commit="$(git -C "$root" rev-parse --short HEAD)"
[ -z "$(git -C "$root" status --porcelain --untracked-files=no)" ] ||
  echo "build_budget: the work tree has uncommitted changes; measuring HEAD ($commit) without them" >&2

# 1. The main job: clone to report.
rm -rf "$work/run"
t0=$SECONDS
git clone -q "$root" "$work/run"
# Each line of standard output with its second since the clone began; the first that is not the build's
# progress ("[k/n] ...") is the main job's first output.
while IFS= read -r line; do
  printf '%d %s\n' $((SECONDS - t0)) "$line" >> "$work/run.log"
done < <(bash "$work/run/scripts/setup.sh" run 2> "$work/run.err")
run_total=$((SECONDS - t0))
first="$(awk '$2 !~ /^\[[0-9]+\/[0-9]+\]/ { print $1; exit }' "$work/run.log")"
[ -f "$work/run/out/default/index.html" ] || { echo "build_budget: setup.sh run wrote no report" >&2; exit 1; }
run_phases="$(sed -n '/phase times/,$p' "$work/run.err")"

# 2. CI in a fresh clone: its stage table and setup.sh's phase tables.
rm -rf "$work/ci"
git clone -q "$root" "$work/ci"
t0=$SECONDS
(cd "$work/ci" && CI=true bash .ci/run > "$work/ci.log" 2>&1) || { echo "build_budget: .ci/run failed, see $work/ci.log" >&2; exit 1; }
ci_total=$((SECONDS - t0))

# 3. Incremental: one library source touched, the CLI rebuilt.
touch "$work/ci/src/rbcstab/model/scene.cpp"
t0=$SECONDS
cmake --build "$work/ci/build/release" --target rbcstab_cli > /dev/null
incremental=$((SECONDS - t0))
"$work/ci/build/release/bin/rbcstab" --version > /dev/null

echo "Build budget of $commit ($(nproc) cores, $(date -u +%Y-%m-%d), cold, work in $work)"
printf '  %-52s %6s s\n' "setup.sh run: clone to the summary's first line" "$first" "setup.sh run: clone to report written" "$run_total"
printf '  %-52s %6s s\n' "incremental: touch src/rbcstab/model/scene.cpp, CLI" "$incremental" ".ci/run total" "$ci_total"
echo "setup.sh run phases:"
printf '%s\n' "$run_phases"
echo ".ci/run (setup.sh phases, then the stage table):"
grep -A4 'phase times' "$work/ci.log" || true
sed -n '/^CI stages/,$p' "$work/ci.log"
