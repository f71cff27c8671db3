#!/usr/bin/env bash
# History benchmark: what reading each component's history costs a build (issue #25: a build
# with history should take at most 3× the time of one without).
#
# usage: bench/history.sh                 (the 1,000-commit, 50-profile repository)
#        CATALOGUE=10000 bench/history.sh (also a 10,000-profile catalogue with 200 commits)
#        RUNS=5 …                          (runs per measurement, the median is reported; default 3)
#        BENCH_DIR=/dev/shm/h …            (where repositories and outputs go; default /tmp/rtcdoc-history)
#        BASELINE=/path/to/rtcdoc …        (an older binary measured beside this one, same runs)
#        FORMATS="html json" …             (default: html markdown doxygen json)
#        BIN=/path/to/rtcdoc …             (measure that binary; default: cargo build --release)
#
# bench/gen_history.py writes the repositories with git fast-import: 50 profiles cloned from the
# examples, 1,000 commits of realistic edits (ports and parameters added, removed, renamed and
# retyped, descriptions, version bumps, whitespace-only commits, folder moves, two RTCBuilder
# backups); and, with CATALOGUE=N, bench/gen_catalogue.py's N-profile catalogue committed as one
# commit followed by 200 commits editing its profiles. Each build is measured with
# /usr/bin/time: CPU time (user + system, which the other processes of a shared machine disturb
# less than the wall time), wall time and peak RSS; history = 0, the default (100) and
# --history 20 run in alternation, and the ratio of CPU times to the build without history is
# printed per format. Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
work=${BENCH_DIR:-/tmp/rtcdoc-history}
formats=(${FORMATS:-html markdown doxygen json})
mkdir -p "$work"
if [ -n "${BIN:-}" ]; then
  bin=$BIN
else
  cargo build --release --quiet
  bin=$PWD/target/release/rtcdoc
fi

# generate DIR ARGS...: the repository, generated once per generator version and arguments.
generate() {
  local dir=$1; shift
  local stamp
  stamp=$( (cat bench/gen_history.py bench/gen_catalogue.py; echo "$@") | sha1sum | cut -c1-16)
  if [ "$(cat "$dir.stamp" 2>/dev/null)" != "$stamp" ]; then
    rm -rf "$dir"
    "$@" >/dev/null
    echo "$stamp" >"$dir.stamp"
  fi
}

# measure OUT CMD...: prints "cpu_s wall_s rss_mb" of one run of CMD (OUT removed first).
measure() {
  local out=$1; shift
  rm -rf "$out"
  /usr/bin/time -f "%U %S %e %M" -o "$work/time" "$@" >/dev/null 2>"$work/err" || {
    echo "failed: $*" >&2; tail -5 "$work/err" >&2; return 1
  }
  awk '{ printf "%.2f %.2f %.0f\n", $1 + $2, $3, $4 / 1024 }' "$work/time"
}

median() { python3 -c '
import sys
rows = [list(map(float, l.split())) for l in sys.stdin if l.strip()]
med = lambda v: sorted(v)[len(v) // 2]
print(f"{med([r[0] for r in rows]):.2f} {med([r[1] for r in rows]):.2f} {max(r[2] for r in rows):.0f}")'; }

# bench NAME SRC: every format, history 0 / default / 20 in alternation.
bench() {
  local name=$1 src=$2
  local bins=("$bin")
  [ -n "${BASELINE:-}" ] && bins+=("$BASELINE")
  for fmt in "${formats[@]}"; do
    declare -A res=()
    for ((r = 0; r < runs; r++)); do
      for b in "${bins[@]}"; do
        for h in 0 default 20; do
          local args=(build "$src" -f "$fmt" -o "$work/out" -q)
          [ "$h" != default ] && args+=(--history "$h")
          res["$b $h"]+="$(measure "$work/out" "$b" "${args[@]}")"$'\n'
        done
      done
    done
    for b in "${bins[@]}"; do
      local label=rtcdoc
      [ "$b" != "$bin" ] && label=baseline
      read -r c0 _ _ < <(printf '%s' "${res["$b 0"]}" | median)
      for h in 0 default 20; do
        read -r c w m < <(printf '%s' "${res["$b $h"]}" | median)
        python3 -c "print(f'| $name | $label $fmt | $h | $c | $w | $m | {$c/max($c0,0.001):.2f} |')"
      done
    done
  done
}

echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| repository | build | history | CPU s (user+sys) | wall s | peak RSS MB | CPU ÷ history 0 |"
echo "|---|---|---|---:|---:|---:|---:|"
generate "$work/h1k" python3 bench/gen_history.py "$work/h1k"
bench "1,000 commits, 50 profiles" "$work/h1k"
if [ -n "${CATALOGUE:-}" ]; then
  n=$CATALOGUE
  generate "$work/cat-$n" python3 bench/gen_catalogue.py "$n" "$work/cat-$n"
  generate "$work/cat-$n-git" python3 bench/gen_history.py "$work/cat-$n-git" --from "$work/cat-$n" --commits 200
  bench "$n profiles, 200 commits" "$work/cat-$n-git"
fi
rm -rf "$work/out"
echo
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
