#!/usr/bin/env bash
# Install what is missing (Debian 12, apt-get) and build fosls-contact in build/.
#
#   scripts/setup.sh            # or: source scripts/setup.sh
#   scripts/setup.sh --sanitize # build-asan/ instead: the same Release
#                               # build with AddressSanitizer and UBSan
#                               # (CMake option FOSLS_SANITIZE=address)
#
# Idempotent: apt-get runs only if a package is missing; cmake and make only
# rebuild what changed. Build messages go to stderr, so that the stdout of
# scripts/run.sh is the program's own output.
# Environment: FOSLS_JOBS (default 2) = parallel make jobs; FOSLS_TARGET
# (default all) = the make target (.ci/run: sanitize_tests);
# FOSLS_UNITY_BUILD=ON|OFF (default: as configured before, else OFF) = CMake's
# unity build, which compiles the sources in batches of 8: 38% less CPU
# for a build from scratch (577 s against 929 s, built one after the
# other here), but a
# change to one source recompiles its batch, so .ci/run uses it and a
# working copy does not.

export DEBIAN_FRONTEND=noninteractive
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

fosls_setup() (
  set -euo pipefail
  local root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

  local packages=(libdeal.ii-dev cmake g++ make numdiff openmpi-bin python3
                  python3-matplotlib)
  local missing=()
  local p
  for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null |
         grep -q 'install ok installed'; then
      missing+=("$p")
    fi
  done
  if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}" >&2
    local sudo=()
    if [[ $(id -u) -ne 0 ]]; then
      command -v sudo >/dev/null ||
        { echo "setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
      sudo=(sudo -E)
    fi
    "${sudo[@]}" apt-get update -q >&2
    "${sudo[@]}" apt-get install -y -q \
      "${missing[@]}" >&2
  fi

  local build=build options=(-DCMAKE_BUILD_TYPE=Release)
  case "${1:-}" in
    "") ;;
    --sanitize) build=build-asan options+=(-DFOSLS_SANITIZE=address) ;;
    *) echo "setup: unknown argument '$1' (the only one is --sanitize)" >&2; exit 1 ;;
  esac
  if [[ -n ${FOSLS_UNITY_BUILD:-} ]]; then
    options+=(-DCMAKE_UNITY_BUILD="$FOSLS_UNITY_BUILD")
  fi
  mkdir -p "$root/$build"
  cd "$root/$build"
  # re-run cmake every time: cheap, and it picks up new source/test files
  # (the sources are collected by file(GLOB_RECURSE))
  cmake "${options[@]}" .. >&2
  make -j"${FOSLS_JOBS:-2}" "${FOSLS_TARGET:-all}" >&2
)

# executed or sourced: the status of the script is that of the setup
fosls_setup "$@"
