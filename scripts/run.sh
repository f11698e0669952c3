#!/usr/bin/env bash
# Build (if needed) and run one scene from the repository root:
#
#   scripts/run.sh [SCENE.prm] [--set "Section/Name=value" ...]
#
# SCENE.prm defaults to prm/square.prm. A relative SCENE path is taken
# relative to the current directory if it exists there, else relative to the
# repository root. Results go to the scene's Output/Directory (relative to the
# repository root).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# deal.II reads DEAL_II_NUM_THREADS while the program loads, before main():
# anything but a whole number > 0 aborts it there with a stack trace, which
# the program cannot catch. Refuse it here, in one line. (Solver/Threads is
# the way to choose the number of threads.)
if [[ -v DEAL_II_NUM_THREADS ]] &&
  ! [[ "$DEAL_II_NUM_THREADS" =~ ^0*[1-9][0-9]{0,5}$ ]]; then
  shown="${DEAL_II_NUM_THREADS//[^[:print:]]/?}"
  echo "fosls-contact: error in environment: DEAL_II_NUM_THREADS='${shown:0:40}'" \
    "is not a whole number > 0 (deal.II would abort before the program starts);" \
    "unset it and choose the threads with --set \"Solver/Threads=N\"" >&2
  exit 1
fi

scene="prm/square.prm"
if (($# > 0)) && [[ "$1" != -* ]]; then
  scene="$1"
  shift
fi
# resolve the scene before changing directory
if [[ "$scene" != /* && -e "$scene" ]]; then
  scene="$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")"
fi

bash "$root/scripts/setup.sh"

cd "$root"
exec "$root/build/fosls-contact" "$scene" "$@"
