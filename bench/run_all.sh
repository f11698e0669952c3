#!/usr/bin/env bash
# Build fosls-contact, run every benchmark case sequentially and regenerate
# doc/results.md, doc/level_costs.md and doc/figures/*.png from the
# measurements.
#
#   bench/run_all.sh            # from any directory
#   bench/run_all.sh --report   # only regenerate the report from bench/results/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
# the system python (where apt installs python3-matplotlib), not a pyenv shim
py=python3; [[ -x /usr/bin/python3 ]] && py=/usr/bin/python3
if ! "$py" -c 'import matplotlib' 2>/dev/null; then
  sudo=(); [[ $(id -u) -ne 0 ]] && sudo=(sudo -E)
  "${sudo[@]}" apt-get update -q >&2
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q python3-matplotlib >&2
fi
if [[ "${1:-}" != "--report" ]]; then
  mkdir -p "$root/bench/results"
  "$py" "$root/bench/run_cases.py" | tee "$root/bench/results/run_cases.log"
  # where the cycles' time goes, level by level (doc/level_costs.md)
  "$py" "$root/bench/level_costs.py" | tee "$root/bench/results/level_costs.log"
  # pictures of solutions (doc/figures/solution_*.png)
  "$py" "$root/bench/figures.py"
fi
"$py" "$root/bench/make_report.py"
