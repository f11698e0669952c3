#!/usr/bin/env bash
# Work-precision study: run every case of bench/work_precision.py
# sequentially (at most ~31 minutes on a 2-core machine), then write doc/work_precision.md, doc/work_precision.csv and
# doc/figures/wp_*.png.
#
#   bench/work_precision.sh              # from any directory; the full study
#   bench/work_precision.sh --report     # only regenerate the report from the CSV
#   bench/work_precision.sh --budget 120 --max-level-2d 5 --max-level-3d 4   # quick test
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# the system python (where apt installs python3-matplotlib), not a pyenv shim
py=python3; [[ -x /usr/bin/python3 ]] && py=/usr/bin/python3
if ! "$py" -c 'import matplotlib' 2>/dev/null; then
  sudo=(); [[ $(id -u) -ne 0 ]] && sudo=(sudo -E)
  "${sudo[@]}" apt-get update -q >&2
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-matplotlib >&2
fi
if [[ ! -x "$root/build/fosls-contact" ]]; then
  "$root/scripts/setup.sh"
fi
if [[ "${1:-}" != "--report" ]]; then
  mkdir -p "$root/bench/results/work_precision"
  "$py" "$root/bench/work_precision.py" "$@" | tee "$root/bench/results/work_precision/run.log"
fi
"$py" "$root/bench/make_work_precision_report.py"
