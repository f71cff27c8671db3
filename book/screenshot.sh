#!/usr/bin/env bash
# Regenerates book/src/images/component-page.png and its Japanese twin
# book/ja/src/images/component-page.png (the site built with --language ja): the example site's
# PathPlanner page, taken with headless Chromium (Debian package `chromium`; the Japanese one needs
# a CJK font, e.g. fonts-noto-cjk).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo run --release --quiet -- build examples -o "$out/site" -q
chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$out/profile" --hide-scrollbars \
  --window-size=1100,1400 --screenshot=book/src/images/component-page.png \
  "file://$out/site/components/pathplanner.html"
cargo run --release --quiet -- build examples -o "$out/site-ja" -q --language ja
chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$out/profile" --hide-scrollbars \
  --window-size=1100,1400 --screenshot=book/ja/src/images/component-page.png \
  "file://$out/site-ja/components/pathplanner.html"
