#!/usr/bin/env bash
# Run every benchmark against the installed package (set up by scripts/setup.sh).
# The venv is scripts/setup.sh's: set SARKP_VENV to use your own (the peers of
# bench_kinematics.py, pylinkage[numba], mechanism and kinepy, are looked for there).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
cd /tmp
uptime
for b in "$here"/benchmarks/bench_*.py; do
  echo "== $(basename "$b")"
  "$bin/python" "$b"
done
