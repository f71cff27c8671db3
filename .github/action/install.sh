#!/usr/bin/env bash
# Step 3 of the rtcdoc action (action.yml), run when the cache has no binary for this source:
# builds and installs rtcdoc from the action's own checkout into ~/.cargo/bin (the cached path).
#
# Environment: GITHUB_ACTION_PATH (GitHub sets it), HOME.
set -euo pipefail
: "${GITHUB_ACTION_PATH:?GITHUB_ACTION_PATH is not set (this script is a step of action.yml)}"

if ! command -v cargo >/dev/null 2>&1; then
  echo "::error::cargo is not on PATH: add a Rust toolchain step (e.g. 'uses: dtolnay/rust-toolchain@stable') before the rtcdoc action"
  exit 2
fi
echo "Installing rtcdoc from $GITHUB_ACTION_PATH (the first build compiles about 170 crates)"
cargo install --path "$GITHUB_ACTION_PATH" --locked --force --root "$HOME/.cargo"
"$HOME/.cargo/bin/rtcdoc" --version
