#!/usr/bin/env bash
# Regenerates book/src/images/component-page.png: the example site's PathPlanner page, taken with
# headless Chromium (Debian package `chromium`).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo run --release --quiet -- build examples -o "$out/site" -q
chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$out/profile" --hide-scrollbars \
  --window-size=1100,1400 --screenshot=book/src/images/component-page.png \
  "file://$out/site/components/pathplanner.html"
