#!/usr/bin/env bash
# [[source]] benchmark (issue #53): what N `[[source]]` repositories cost a build, against the
# same N profiles read from one directory.
#
# usage: bench/sources.sh                 (300 sources)
#        SOURCES="300 1000" bench/sources.sh
#        RUNS=5 …                          (runs per measurement, the median is reported; default 3)
#        BENCH_DIR=/dev/shm/s …            (where repositories, caches and outputs go; default
#                                           /dev/shm/rtcdoc-sources, on tmpfs)
#        BASELINE=/path/to/rtcdoc …        (an older binary measured beside this one, same runs)
#        BIN=/path/to/rtcdoc …             (measure that binary; default: cargo build --release)
#        JOBS=N …                          (passed as --jobs to BIN; the baseline gets none)
#
# Each source is a local git repository with one profile (from examples/) and two commits; the
# configuration lists them as file:// URLs. Measured per binary: "cold" (empty cache, no lock:
# every repository fetched), "warm" (cache and lock filled: nothing fetched) and "one dir" (the
# N profiles copied into one directory, no source). Also the git processes a warm build runs
# (strace, when installed) and the warm build's peak RSS (median, MB). Prints a Markdown table of
# median wall times.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
work=${BENCH_DIR:-/dev/shm/rtcdoc-sources}
counts=(${SOURCES:-300})
mkdir -p "$work"
if [ -n "${BIN:-}" ]; then
  bin=$BIN
else
  cargo build --release --quiet
  bin=$PWD/target/release/rtcdoc
fi
profile=$(find examples -name RTC.xml | sort | head -1)
[ -n "$profile" ] || { echo "no examples/**/RTC.xml" >&2; exit 1; }

# generate N: N repositories, their rtcdoc.toml and the one-directory copy, once per N.
generate() {
  local n=$1 d=$work/n$1
  [ -f "$d/done" ] && return
  rm -rf "$d"; mkdir -p "$d/repos" "$d/flat" "$d/proj"
  for i in $(seq -w 1 "$n"); do
    local r=$d/repos/comp$i
    mkdir -p "$r"
    sed "0,/rtc:name=\"[^\"]*\"/s//rtc:name=\"Comp$i\"/" "$profile" >"$r/RTC.xml"
    git -C "$r" init -q -b main
    git -C "$r" -c user.name=b -c user.email=b@b add RTC.xml
    git -C "$r" -c user.name=b -c user.email=b@b commit -qm one
    echo "<!-- $i -->" >>"$r/RTC.xml"
    git -C "$r" -c user.name=b -c user.email=b@b commit -qam two
    mkdir -p "$d/flat/comp$i"; cp "$r/RTC.xml" "$d/flat/comp$i/"
    printf '[[source]]\ngit = "file://%s"\n\n' "$r" >>"$d/proj/rtcdoc.toml"
  done
  touch "$d/done"
}

# wall CMD...: the wall time of one run of CMD, in seconds.
# (The peak RSS of that run, in kB, is left in $work/rss.)
wall() {
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" >/dev/null 2>"$work/err" || {
    echo "failed: $*" >&2; tail -5 "$work/err" >&2; return 1
  }
  cut -d' ' -f2 "$work/time" >"$work/rss"
  cut -d' ' -f1 "$work/time"
}
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# run BIN EXTRA N: prints "cold warm onedir gits rss" for one binary.
run() {
  local b=$1 extra=$2 d=$work/n$3
  local cold=() warm=() one=() rss=()
  for _ in $(seq "$runs"); do
    rm -rf "$d/cache" "$d/proj/rtcdoc.lock"
    cold+=("$(wall "$b" build $extra -q --cache-dir "$d/cache" --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json)")
    warm+=("$(wall "$b" build $extra -q --cache-dir "$d/cache" --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json)")
    rss+=("$(cat "$work/rss")")
    one+=("$(wall "$b" build -q "$d/flat" -o "$d/out1" -f json)")
  done
  local gits=-
  if command -v strace >/dev/null; then
    strace -f -qq -z -e trace=execve -o "$work/strace" "$b" build $extra -q --cache-dir "$d/cache" \
      --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json >/dev/null 2>&1 || true
    gits=$(grep -c 'execve("[^"]*/git"' "$work/strace" || true)
  fi
  echo "$(printf '%s\n' "${cold[@]}" | median) $(printf '%s\n' "${warm[@]}" | median) $(printf '%s\n' "${one[@]}" | median) $gits $(printf '%s\n' "${rss[@]}" | median)"
}

echo "| sources | binary | cold s | warm s | one dir s | warm/one dir | cold/warm | git processes (warm) | warm peak RSS MB |"
echo "|---|---|---|---|---|---|---|---|---|"
for n in "${counts[@]}"; do
  generate "$n"
  for which in baseline this; do
    if [ "$which" = baseline ]; then
      [ -n "${BASELINE:-}" ] || continue
      read -r c w o g r < <(run "$BASELINE" "" "$n")
    else
      read -r c w o g r < <(run "$bin" "${JOBS:+--jobs $JOBS}" "$n")
    fi
    awk -v n="$n" -v b="$which" -v c="$c" -v w="$w" -v o="$o" -v g="$g" -v r="$r" \
      'BEGIN { printf "| %s | %s | %.2f | %.2f | %.2f | %.1f× | %.1f× | %s | %.1f |\n", n, b, c, w, o, w / o, c / w, g, r / 1024 }'
  done
done
