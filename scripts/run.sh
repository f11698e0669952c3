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
