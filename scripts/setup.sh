#!/usr/bin/env bash
# One-step set-up for a fresh Debian 12 machine: installs the missing Debian packages (needs root,
# or sudo), configures rbcstab in Release with warnings as errors, builds what the mode needs, then
#   run     : builds the library and the command-line tool only, and runs the main job (summary and report of
#             the default scene, or of the scene flags given after 'run')
#   python  : builds the library and the Python module, and makes `import rbcstab` work (a .pth file)
#   test    : builds everything the default suite runs (tests, fuzz-corpus replays, benchmarks, the Python
#             module), makes `import rbcstab` work, and runs the default test suite (ctest, every label but 'slow')
#   build   : builds everything, runs nothing
#   sanitize: builds the 'asan' preset (AddressSanitizer + UndefinedBehaviorSanitizer, every finding fatal) and
#             runs the sanitized suite in it (docs/reliability.md "Sanitizers")
# Environment: RBCSTAB_BUILD_DIR (default build/release), RBCSTAB_ASAN_BUILD_DIR (default build/asan),
# RBCSTAB_JOBS (default: number of cores). ccache is used when installed (docs/building.md).
set -euo pipefail
mode="${1:-run}"
shift || true
case "$mode" in run|python|test|build|sanitize) ;; *) echo "usage: $0 {run|python|test|build|sanitize} [extra args for the main job]" >&2; exit 2;; esac

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Each phase's wall time and the CPU time of its processes, on standard error at the end: the figures of the build
# budget (docs/building.md). `times` runs in this shell (no subshell) so that it sees every finished child.
phase_file="$(mktemp)"
phase_rows=()
cpu_seconds() {  # sets cpu: the user + system seconds of this shell's finished children
  times > "$phase_file"
  cpu="$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.1f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$phase_file")"
}
phase() {  # phase NAME COMMAND...: runs COMMAND and records its wall and CPU seconds
  local name="$1" w0=$SECONDS c0
  shift
  cpu_seconds
  c0="$cpu"
  "$@"
  cpu_seconds
  phase_rows+=("$(printf '%-10s %6d s wall %7.0f s CPU' "$name" $((SECONDS - w0)) "$(awk -v a="$cpu" -v b="$c0" 'BEGIN { print a - b }')")")
}
print_phases() {
  rm -f "$phase_file"
  ((${#phase_rows[@]})) || return 0
  echo "rbcstab setup ($mode): phase times" >&2
  printf '  %s\n' "${phase_rows[@]}" >&2
}
trap print_phases EXIT
build="${RBCSTAB_BUILD_DIR:-$root/build/release}"
jobs="${RBCSTAB_JOBS:-$(nproc)}"

packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libgsl-dev coinor-libipopt-dev libarpack2-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libopenmpi-dev openmpi-bin python3-matplotlib
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-scipy python3-pytest
  python3-nbclient python3-nbformat python3-ipykernel python3-tqdm)
# The test suite also checks the source format (layout.format); the other modes do not need the formatter.
[ "$mode" = test ] && packages+=(clang-format)
# pandas and xarray are optional for users (to_pandas/to_xarray import them), mypy too (the stubs): the suite tests both.
[ "$mode" = test ] && packages+=(python3-pandas python3-xarray python3-mypy)
# The report's browser test (browser.report_page) opens the page in headless Chromium; it is skipped without it.
# Measured on Debian 12: 23 packages, 118 MiB downloaded, 395 MiB installed, 66 s.
[ "$mode" = test ] && packages+=(chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
install_missing() {
  echo "rbcstab setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "rbcstab setup: run as root (or install sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}
if ((${#missing[@]})); then
  phase apt install_missing
fi

if [ "$mode" = sanitize ]; then
  # The sanitizer flags live in the preset only.
  build="${RBCSTAB_ASAN_BUILD_DIR:-$root/build/asan}"
  phase configure cmake -S "$root" --preset asan -B "$build" >/dev/null
else
  phase configure cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBCSTAB_WERROR=ON >/dev/null
fi
# Each mode builds what it runs (docs/building.md): the main job needs the library and the CLI (the report draws
# with python3 and matplotlib, not with the Python module).
case "$mode" in
  run) phase build cmake --build "$build" -j "$jobs" --target rbcstab_cli ;;
  python) phase build cmake --build "$build" -j "$jobs" --target _rbcstab ;;
  *) phase build cmake --build "$build" -j "$jobs" ;;
esac

# `import rbcstab` from any directory with Debian's python3: a .pth file in its site directory names the build's
# package folder (as root the system site directory, otherwise the user's).
if [[ "$mode" =~ ^(python|test|build)$ ]] && [ -d "$build/python/rbcstab" ]; then
  if [ "$(id -u)" -eq 0 ]; then
    site="$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')"
  else
    site="$(/usr/bin/python3 -m site --user-site)"
  fi
  mkdir -p "$site"
  printf '%s\n' "$build/python" > "$site/rbcstab.pth.tmp.$$"
  mv -f "$site/rbcstab.pth.tmp.$$" "$site/rbcstab.pth"
fi

case "$mode" in
  run)
    # The main job on the default scene (paper Fig. 3, out of plane): the summary (regime, thresholds,
    # predictions against simulation) on stdout, then the full report with figures and 3-D shape.
    report_dir="${RBCSTAB_REPORT_DIR:-$root/out/default}"
    mkdir -p "$(dirname "$report_dir")"
    phase summary "$build/bin/rbcstab" summary "$@"
    phase report "$build/bin/rbcstab" report --output "$report_dir" --overwrite "$@"
    ;;
  test)
    # OpenMPI refuses to run as root unless told; CI runs as root.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    phase suite ctest --test-dir "$build" -LE slow --output-on-failure -j "$jobs" --timeout 900
    ;;
  sanitize)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # Stop at the first finding with a stack trace; options given by the caller come last and win.
    export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
    export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
    phase suite ctest --test-dir "$build" -LE slow --output-on-failure -j "$jobs" --timeout 900
    ;;
  build|python) ;;
esac
