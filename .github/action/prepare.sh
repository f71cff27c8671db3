#!/usr/bin/env bash
# Step 1 of the rtcdoc action (action.yml): the cache key of the installed binary, and
# ~/.cargo/bin on PATH for the later steps (also when the install step is skipped on a cache hit).
#
# The key is the crate version plus a hash of everything compiled into the binary (Cargo.toml,
# Cargo.lock, src/, themes/) in the action's own checkout: the binary is rebuilt exactly when the
# action's source changes. (`hashFiles()` cannot be used: it only sees files under
# GITHUB_WORKSPACE, and the action's checkout is outside it.)
#
# Environment (GitHub sets it): GITHUB_ACTION_PATH, GITHUB_OUTPUT, GITHUB_PATH (optional), HOME.
set -euo pipefail
: "${GITHUB_ACTION_PATH:?GITHUB_ACTION_PATH is not set (this script is a step of action.yml)}"
: "${GITHUB_OUTPUT:?GITHUB_OUTPUT is not set (this script is a step of action.yml)}"
cd "$GITHUB_ACTION_PATH"

if command -v sha256sum >/dev/null 2>&1; then
  sha() { sha256sum; }
elif command -v shasum >/dev/null 2>&1; then
  sha() { shasum -a 256; }
else
  echo "::error::neither sha256sum nor shasum is available to compute the cache key"
  exit 2
fi

version="$(awk -F'"' '/^\[package\]/ { p = 1; next } /^\[/ { p = 0 } p && /^version *=/ { print $2; exit }' Cargo.toml)"
if [ -z "$version" ]; then
  echo "::error::no [package] version in $GITHUB_ACTION_PATH/Cargo.toml"
  exit 2
fi
# Each file's hash and relative path, in a fixed order, hashed again: independent of where the
# action is checked out.
hash="$({ printf '%s\n' Cargo.toml Cargo.lock; find src themes -type f; } | LC_ALL=C sort |
  while IFS= read -r file; do
    printf '%s  %s\n' "$(sha <"$file" | cut -c1-64)" "$file"
  done | sha | cut -c1-16)"

echo "key=rtcdoc-$version-$hash" >>"$GITHUB_OUTPUT"
echo "version=$version" >>"$GITHUB_OUTPUT"
if [ -n "${GITHUB_PATH:-}" ]; then
  echo "$HOME/.cargo/bin" >>"$GITHUB_PATH"
fi
echo "rtcdoc $version, cache key rtcdoc-$version-$hash"
