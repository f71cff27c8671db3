#!/usr/bin/env bash
# Builds rtcdoc's Python wheel for this platform with maturin (pyproject.toml: bindings = "bin"),
# installs it into a fresh virtual environment and runs the installed `rtcdoc` from there:
# `--version` must print Cargo.toml's version and `build examples` must write a site.
#
#   bash .ci/wheel.sh            # from anywhere; uses python3 (or $PYTHON)
#
# maturin itself comes from PyPI (current 1.x release) into a tools venv kept under the cargo
# target directory, which is also the build's: the wheel's binary is built with Cargo.toml's
# `dist` profile (fat LTO, one code unit; pyproject.toml's `profile = "dist"`), in
# $CARGO_TARGET_DIR/dist (CARGO_TARGET_DIR, default `target`).
# Exits non-zero, with a message saying what to do, on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PIP_DISABLE_PIP_VERSION_CHECK=1
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}"

fail() {
  echo "wheel.sh: error: $*" >&2
  exit 1
}

python="${PYTHON:-python3}"
command -v "$python" >/dev/null 2>&1 ||
  fail "$python not found: install Python 3 (Debian/Ubuntu: apt-get install python3 python3-venv)"

work="$(mktemp -d "${TMPDIR:-/tmp}/rtcdoc-wheel.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# Debian and Ubuntu ship python3 without ensurepip: `python3 -m venv` fails until python3-venv is
# installed. Install it when we can (root with apt-get), otherwise say what to install.
if ! "$python" -m venv "$work/probe" >"$work/probe.log" 2>&1; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "== wheel: '$python -m venv' does not work; installing python3-venv"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends python3-venv >/dev/null ||
      fail "apt-get install python3-venv failed"
    "$python" -m venv "$work/probe" >"$work/probe.log" 2>&1 ||
      fail "'$python -m venv' still fails after installing python3-venv: $(cat "$work/probe.log")"
  else
    fail "'$python -m venv' does not work (install python3-venv, or set PYTHON to a Python 3 with venv): $(cat "$work/probe.log")"
  fi
fi
rm -rf "$work/probe"

version="$(awk -F'"' '/^\[package\]/ { p = 1; next } /^\[/ { p = 0 } p && /^version *=/ { print $2; exit }' Cargo.toml)"
[ -n "$version" ] || fail "no version in the [package] table of Cargo.toml"

# maturin, in a venv of its own under the target directory (reused between runs, upgraded to the
# current release each time).
tools="$CARGO_TARGET_DIR/ci/maturin-venv"
if [ ! -x "$tools/bin/python" ]; then
  rm -rf "$tools"
  "$python" -m venv "$tools" || fail "cannot create the maturin venv $tools"
fi
echo "== wheel: installing maturin from PyPI"
"$tools/bin/python" -m pip install --quiet --upgrade 'maturin>=1.9,<2' ||
  fail "pip could not install maturin from PyPI (network? proxy? see the pip output above)"
maturin="$tools/bin/maturin"
"$maturin" --version

echo "== wheel: maturin build --profile dist --locked"
start=$(date +%s)
"$maturin" build --profile dist --locked --out "$work/wheels" ||
  fail "maturin build failed (see its output above)"
seconds=$(($(date +%s) - start))

shopt -s nullglob
wheels=("$work/wheels"/rtcdoc-"$version"-*.whl)
shopt -u nullglob
[ ${#wheels[@]} -eq 1 ] ||
  fail "expected one wheel rtcdoc-$version-*.whl, found: $(ls -A "$work/wheels" 2>/dev/null | tr '\n' ' ')"
wheel="${wheels[0]}"
bytes=$(wc -c <"$wheel" | tr -d ' ')
echo "== wheel: $(basename "$wheel"): $bytes bytes ($((bytes / 1024)) KiB), built in ${seconds} s"

echo "== wheel: installing it into a fresh venv"
venv="$work/venv"
"$python" -m venv "$venv" || fail "cannot create the venv $venv"
"$venv/bin/python" -m pip install --quiet --no-index --no-deps "$wheel" ||
  fail "pip could not install $(basename "$wheel") into a fresh venv"
rtcdoc="$venv/bin/rtcdoc"
[ -x "$rtcdoc" ] || fail "the wheel did not install an executable $rtcdoc"

got="$("$rtcdoc" --version)" || fail "'$rtcdoc --version' failed"
[ "$got" = "rtcdoc $version" ] ||
  fail "'rtcdoc --version' from the wheel printed '$got', expected 'rtcdoc $version'"
echo "== wheel: $got"

status=0
"$rtcdoc" build examples -o "$work/site" || status=$?
[ "$status" -eq 0 ] || fail "'rtcdoc build examples' from the wheel exited $status"
[ -f "$work/site/index.html" ] || fail "'rtcdoc build examples' from the wheel wrote no index.html"
echo "== wheel: ok (the wheel's rtcdoc built examples into a site with index.html)"
