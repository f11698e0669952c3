#!/usr/bin/env bash
# Build (if needed) and run the test suite:
#
#   scripts/test.sh [ctest arguments, e.g. -R mms -V]
#
# The exit code is ctest's.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bash "$root/scripts/setup.sh"

cd "$root/build"
set +e
ctest --output-on-failure -j2 "$@"
status=$?
set -e
exit "$status"
