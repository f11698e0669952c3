#!/usr/bin/env bash
# Build (if needed) and run the test suite:
#
#   scripts/test.sh [ctest arguments, e.g. -R mms -V]
#   scripts/test.sh --sanitize [ctest arguments]
#
# --sanitize: build and run in build-asan/, with AddressSanitizer and UBSan
# (scripts/setup.sh --sanitize); a finding fails the test that met it.
# .ci/run runs `--sanitize -C long -L sanitize` there (README, "Two commands").
# The exit code is ctest's.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

build=build setup=()
if [[ ${1:-} == --sanitize ]]; then
  shift
  build=build-asan setup=(--sanitize)
fi
bash "$root/scripts/setup.sh" "${setup[@]}"

cd "$root/$build"
set +e
ctest --output-on-failure -j2 "$@"
status=$?
set -e
exit "$status"
