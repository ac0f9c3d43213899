#!/usr/bin/env bash
# Set everything up, then run the test suite against the installed package.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
cd "$here"
"$bin/pytest" -p no:cacheprovider "$@"
