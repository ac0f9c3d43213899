#!/usr/bin/env bash
# Main job: the course project of chapter 10 (program X) computed again, stage by stage,
# with its pictures, then every printed figure reproduced so far compared with the book
# cell by cell (as-printed mode; the rules: docs/judging.md), each figure ending with its line
# of the summary table (the same classes and counts), then the table itself.
# Extra arguments go to the diff (e.g. --mode corrected).  Pictures: $SARKP_PLOTS
# (default /tmp/sarkp-plots).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
cd /tmp   # never import from the source tree
"$bin/sarkp" book run X --plots "${SARKP_PLOTS:-/tmp/sarkp-plots}"
echo
"$bin/sarkp" book diff all "$@"
