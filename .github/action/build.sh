#!/usr/bin/env bash
# Step 5 of the rtcdoc action (action.yml): `rtcdoc build`.
#
# Environment (the step's `env:`, from the action's inputs):
#   INPUT_DIR    directory or file of profiles              (input `input`)
#   OUTPUT_DIR   output directory                           (input `output`)
#   FORMATS      html, markdown, doxygen, json; several separated by commas or spaces
#                (several at once go to OUTPUT_DIR/<format>/) (input `formats`)
#   BASE_URL     URL the site is published at, may be empty (input `base-url`)
#   BUILD_ARGS   extra arguments, split on whitespace       (input `args`)
# Writes `site=OUTPUT_DIR` to GITHUB_OUTPUT.
set -euo pipefail
: "${GITHUB_OUTPUT:?GITHUB_OUTPUT is not set (this script is a step of action.yml)}"
input="${INPUT_DIR:-.}"
output="${OUTPUT_DIR:-site}"

formats="$(printf '%s' "${FORMATS:-}" | tr -s ' ,\t\n' ',' | sed 's/^,//; s/,$//')"
args=(build -o "$output" -f "${formats:-html}")
if [ -n "${BASE_URL:-}" ]; then
  args+=(--base-url "$BASE_URL")
fi
extra=()
read -r -a extra -d '' <<<"${BUILD_ARGS:-}" || true

rtcdoc "${args[@]}" ${extra[@]+"${extra[@]}"} -- "$input"
echo "site=$output" >>"$GITHUB_OUTPUT"
