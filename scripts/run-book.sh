#!/usr/bin/env bash
# Main job: reproduce every printed figure implemented so far and compare it with the
# book, cell by cell (as-printed mode, the book's own arithmetic).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
cd /tmp   # never import from the source tree
"$bin/sarkp" book diff all "$@"
