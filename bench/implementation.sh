#!/usr/bin/env bash
# The cost of the implementation check (issue 51): the corpus-shaped catalogue built with and
# without the code RTCBuilder generates beside each profile, side by side.
#
# usage: bench/implementation.sh [N]          (default 3000 profiles)
#        RUNS=5 bench/implementation.sh 10000  (pairs of runs; default 5)
#        BENCH_DIR=/dev/shm/b …                (where catalogues and outputs go; default /tmp)
#        BIN=/path/to/rtcdoc …                 (measure this binary; default: cargo build --release)
#        CORPUS=DIR …                          (default ../shared/corpus/rtc-xml)
#
# Both catalogues are `bench/gen_catalogue.py N DIR --shape corpus`, byte for byte the same
# profiles; the second has `--implementation` (C++ src/<Name>.cpp and include/<Name>/<Name>.h,
# or Python <Name>.py, with the spec array, registrations and callbacks, 6-12 KB each). Each pair
# runs `rtcdoc build -f html` on one, then on the other (alternating which goes first), under
# /usr/bin/time -v; the report is the median wall time of each, the median of the per-pair
# ratios, and the largest peak RSS of each. The issue's bar: ratio <= 1.5, RSS <= 1.25x.
# `rtcdoc check` is measured the same way. Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-3000}
runs=${RUNS:-5}
work=${BENCH_DIR:-/tmp/rtcdoc-bench-impl}
corpus=${CORPUS:-$PWD/../shared/corpus/rtc-xml}
mkdir -p "$work"
if [ ! -x /usr/bin/time ] && [ "$(id -u)" = 0 ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time >/dev/null
fi
if [ -n "${BIN:-}" ]; then bin=$(realpath "$BIN"); else
  cargo build --release --quiet; bin=$PWD/target/release/rtcdoc; fi
plain=$work/cat-$n
code=$work/cat-$n-code
python3 bench/gen_catalogue.py "$n" "$plain" --shape corpus --corpus "$corpus" >/dev/null
python3 bench/gen_catalogue.py "$n" "$code" --shape corpus --corpus "$corpus" --implementation >/dev/null
files=$(find "$code" -name '*.cpp' -o -name '*.h' -o -name '*.py' | wc -l)
kb=$(find "$code" \( -name '*.cpp' -o -name '*.h' -o -name '*.py' \) -printf '%s\n' | awk '{s+=$1} END {printf "%.0f", s/1024}')

# one CMD...: "seconds rss_mb" of one run (exit 1 of check with profile errors is a result).
one() {
  local log=$work/time.log
  sync
  /usr/bin/time -v "$@" >/dev/null 2>"$log" || grep -q 'Exit status: 1$' "$log" || {
    echo "failed: $*" >&2; tail -5 "$log" >&2; exit 1; }
  awk -F': ' '/Elapsed \(wall clock\)/ {split($2, t, ":"); w = t[length(t)] + (length(t) > 1 ? t[length(t)-1] * 60 : 0)}
              /Maximum resident set size/ {r = $2} END {printf "%.3f %.0f\n", w, r / 1024}' "$log"
}

# pairs WHAT ARGS...: RUNS alternating pairs of `rtcdoc ARGS` on the two catalogues (the
# catalogue's place is the token CAT, the output's OUT).
pairs() {
  local what=$1; shift
  local rows=()
  for ((r = 0; r < runs; r++)); do
    local a b
    for side in plain code; do
      local cat=$plain; [ "$side" = code ] && cat=$code
      local args=("${@//CAT/$cat}"); args=("${args[@]//OUT/$work/out-$side}")
      rm -rf "$work/out-$side"
      if [ "$side" = plain ]; then a=$(one "$bin" "${args[@]}"); else b=$(one "$bin" "${args[@]}"); fi
    done
    rows+=("$a $b")
  done
  printf '%s\n' "${rows[@]}" | python3 -c '
import sys
what = sys.argv[1]
rows = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
med = lambda v: sorted(v)[len(v) // 2]
ta, ra, tb, rb = [r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows], [r[3] for r in rows]
ratio = med([b / max(a, 1e-3) for a, _, b, _ in rows])
print(f"| {what} | {med(ta):.2f} | {med(tb):.2f} | {ratio:.2f} | {max(ra):.0f} | {max(rb):.0f} | {max(rb) / max(ra):.2f} |")
' "$what"
}

echo "Corpus-shaped catalogue of $n profiles; with code: $files source files, $kb KiB. $runs pairs of runs."
echo
echo "| command | without code s | with code s | time ratio (median of pairs) | RSS without MB | RSS with MB | RSS ratio |"
echo "|---|---:|---:|---:|---:|---:|---:|"
pairs "build -f html" build CAT -f html -o OUT -q
pairs "check" check CAT -q
