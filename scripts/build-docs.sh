#!/usr/bin/env bash
# Build the documentation: the pages a student learns from (docs/concepts.md,
# tutorial.md, from-the-book.md: their Python blocks run while the page is read, each
# followed by what it prints and draws), the API reference from the docstrings
# (numpydoc), the gallery (docs/examples, run by sphinx-gallery) and docs/ERRATA.md
# (myst-parser).  Sets up sarkp first (scripts/setup.sh), installs the documentation
# tools into the same virtual environment, and runs sphinx-build with warnings as
# errors: a warning, or a code block that raises, fails the build.  Output:
# $SARKP_DOCS_OUT (default docs/_build/html).  Extra arguments go to sphinx-build.
# SARKP_NO_SETUP=1 skips the set-up (the package is already installed in $SARKP_VENV).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "${SARKP_NO_SETUP:-0}" = 1 ]; then   # .ci/run: the tests just installed it
  bin="${SARKP_VENV:-$HOME/.cache/sarkp/venv}/bin"
else
  bin="$(bash "$here/scripts/setup.sh" | tail -n 1)"
fi
"$bin/python" -m pip install -q \
  "sphinx>=7" \
  "numpydoc>=1.6" \
  "myst-parser>=2" \
  "sphinx-gallery>=0.15" \
  matplotlib >&2
out="${SARKP_DOCS_OUT:-$here/docs/_build/html}"
cd /tmp   # import the installed sarkp, never the source tree's python/ folder
"$bin/python" -P -m sphinx -W --keep-going -q -b html -d "$here/docs/_build/doctrees" \
  "$@" "$here/docs" "$out"
echo "documentation: $out/index.html"
