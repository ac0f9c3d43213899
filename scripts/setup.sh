#!/usr/bin/env bash
# Set up everything sarkp needs on a Debian machine that has only Python:
# gfortran, LAPACK and pkg-config (apt-get, when missing), a virtual environment
# outside the source tree, the build and the install of the package.
# Prints the venv's bin directory on its last line.  Idempotent.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="${SARKP_VENV:-$HOME/.cache/sarkp/venv}"

missing=()
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
if ! pkg-config --exists lapack 2>/dev/null; then missing+=(liblapack-dev); fi
if ! python3 -c 'import ensurepip, venv' >/dev/null 2>&1; then missing+=(python3-venv); fi
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "sarkp needs these Debian packages: ${missing[*]}" >&2
    echo "install them as root:  apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  echo "installing ${missing[*]} with apt-get" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >&2
  apt-get install -y -qq "${missing[@]}" >&2
fi

if [ ! -x "$venv/bin/python" ]; then
  echo "creating the virtual environment $venv" >&2
  mkdir -p "$(dirname "$venv")"
  python3 -m venv "$venv" >&2
fi
export PATH="$venv/bin:$PATH"   # meson-python looks for meson and ninja here
python -m pip install -q --upgrade pip >&2
python -m pip install -q numpy meson meson-python ninja fortranformat matplotlib scipy \
  pytest hypothesis mpmath \
  pandas \
  mypy \
  pylinkage \
  dask distributed \
  numpydoc \
  >&2
echo "building and installing sarkp" >&2
python -m pip install -q --no-build-isolation "$here" >&2
echo "$venv/bin"
