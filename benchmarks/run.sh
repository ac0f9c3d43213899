#!/usr/bin/env bash
# Run every benchmark against the installed package (set up by scripts/setup.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
cd /tmp
for b in "$here"/benchmarks/bench_*.py; do
  echo "== $(basename "$b")"
  "$bin/python" "$b"
done
