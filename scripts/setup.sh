#!/usr/bin/env bash
# One-step set-up for a fresh Debian 12 machine: installs the missing Debian packages (needs root,
# or sudo), builds rbcstab in Release with warnings as errors, then
#   run  : runs the main job (summary and report of the default scene, or of the scene flags given after 'run')
#   test : runs the default test suite (ctest, every label except 'slow')
#   build: only installs and builds
#   sanitize: instead builds the 'asan' preset (AddressSanitizer + UndefinedBehaviorSanitizer, every
#             finding fatal) and runs the same default suite in it (docs/reliability.md "Sanitizers")
# Environment: RBCSTAB_BUILD_DIR (default build/release), RBCSTAB_ASAN_BUILD_DIR (default build/asan),
# RBCSTAB_JOBS (default: number of cores).
set -euo pipefail
mode="${1:-run}"
shift || true
case "$mode" in run|test|build|sanitize) ;; *) echo "usage: $0 {run|test|build|sanitize} [extra args for the main job]" >&2; exit 2;; esac

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RBCSTAB_BUILD_DIR:-$root/build/release}"
jobs="${RBCSTAB_JOBS:-$(nproc)}"

packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libgsl-dev coinor-libipopt-dev libarpack2-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libopenmpi-dev openmpi-bin python3-matplotlib
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-scipy python3-pytest
  python3-nbclient python3-nbformat python3-ipykernel python3-tqdm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "rbcstab setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "rbcstab setup: run as root (or install sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ "$mode" = sanitize ]; then
  # The sanitizer flags live in the preset only.
  build="${RBCSTAB_ASAN_BUILD_DIR:-$root/build/asan}"
  (cd "$root" && cmake --preset asan -B "$build" >/dev/null)
else
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBCSTAB_WERROR=ON >/dev/null
fi
cmake --build "$build" -j "$jobs"

# `import rbcstab` from any directory with Debian's python3: a .pth file in its site directory names the build's
# package folder (as root the system site directory, otherwise the user's).
if [ -d "$build/python/rbcstab" ]; then
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
    "$build/bin/rbcstab" summary "$@"
    "$build/bin/rbcstab" report --output "$report_dir" --overwrite "$@"
    ;;
  test)
    # OpenMPI refuses to run as root unless told; CI runs as root.
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    ctest --test-dir "$build" -LE slow --output-on-failure -j "$jobs" --timeout 900
    ;;
  sanitize)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # Stop at the first finding with a stack trace; options given by the caller come last and win.
    export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
    export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
    ctest --test-dir "$build" -LE slow --output-on-failure -j "$jobs" --timeout 900
    ;;
  build) ;;
esac
