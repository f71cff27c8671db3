#!/usr/bin/env bash
# Step 4 of the rtcdoc action (action.yml): `rtcdoc check` on the input, with the exit status
# mapped by `fail-on`:
#   error    the step fails when a profile has an error (rtcdoc check's own exit status)
#   warning  the step fails on errors and on warnings (`--deny warnings`)
#   never    findings are reported (log, outputs, job summary) but never fail the step
# Whatever `fail-on` says, the step fails when rtcdoc cannot run at all (exit 2: a bad flag, an
# input that does not exist, an unreadable file).
#
# Environment (the step's `env:`, from the action's inputs):
#   INPUT_DIR   directory or file to check           (input `input`)
#   FAIL_ON     error | warning | never              (input `fail-on`)
#   CHECK_ARGS  extra arguments, split on whitespace (input `check-args`)
# Writes `errors=N` and `warnings=N` to GITHUB_OUTPUT, and a line to GITHUB_STEP_SUMMARY if set.
set -euo pipefail
: "${GITHUB_OUTPUT:?GITHUB_OUTPUT is not set (this script is a step of action.yml)}"
input="${INPUT_DIR:-.}"

deny=()
case "${FAIL_ON:-error}" in
  error | never) ;;
  warning) deny=(--deny warnings) ;;
  *)
    echo "::error::the rtcdoc action's input fail-on must be error, warning or never (it is '${FAIL_ON}')"
    exit 2
    ;;
esac
extra=()
read -r -a extra -d '' <<<"${CHECK_ARGS:-}" || true

# The counts, from the versioned JSON report (its `summary` object comes last).
report="$(mktemp "${RUNNER_TEMP:-${TMPDIR:-/tmp}}/rtcdoc-check.XXXXXX")"
trap 'rm -f "$report"' EXIT
rtcdoc check --format json ${extra[@]+"${extra[@]}"} -- "$input" >"$report" 2>/dev/null || true
count() {
  sed -n "s/^ *\"$1\": *\\([0-9][0-9]*\\).*/\\1/p" "$report" | tail -n 1
}
errors="$(count errors)"
warnings="$(count warnings)"

# The findings, for people reading the log.
status=0
rtcdoc check ${deny[@]+"${deny[@]}"} ${extra[@]+"${extra[@]}"} -- "$input" || status=$?

if [ -n "$errors" ] && [ -n "$warnings" ]; then
  echo "errors=$errors" >>"$GITHUB_OUTPUT"
  echo "warnings=$warnings" >>"$GITHUB_OUTPUT"
  summary="rtcdoc check \`$input\`: $errors error(s), $warnings warning(s)"
  if [ -n "${GITHUB_STEP_SUMMARY:-}" ]; then
    echo "$summary" >>"$GITHUB_STEP_SUMMARY"
  fi
else
  summary="rtcdoc check \`$input\`"
fi

case "$status" in
  0) ;;
  1)
    if [ "${FAIL_ON:-error}" = never ]; then
      echo "::warning::$summary (fail-on: never, so the job goes on)"
    else
      echo "::error::$summary (fail-on: ${FAIL_ON:-error}; the findings are listed above)"
      exit 1
    fi
    ;;
  *)
    echo "::error::rtcdoc check could not run (exit status $status); see the message above"
    exit "$status"
    ;;
esac
