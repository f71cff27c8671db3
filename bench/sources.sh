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
# (strace, when installed) and the warm build's peak RSS (median, MB). With BASELINE, the two
# binaries run in alternation (run 1 of each, then run 2 …), so that the load of a shared
# machine falls on both alike. Prints a Markdown table of median wall times.
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

# once BIN EXTRA N: prints "cold warm onedir rss" of one run of one binary.
once() {
  local b=$1 extra=$2 d=$work/n$3 c w o
  rm -rf "$d/cache" "$d/proj/rtcdoc.lock"
  c=$(wall "$b" build $extra -q --cache-dir "$d/cache" --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json)
  w=$(wall "$b" build $extra -q --cache-dir "$d/cache" --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json)
  local r; r=$(cat "$work/rss")
  o=$(wall "$b" build -q "$d/flat" -o "$d/out1" -f json)
  echo "$c $w $o $r"
}

# gits BIN EXTRA N: the git processes of a warm build (strace, when installed; the cache and
# lock are those `once` left).
gits() {
  local b=$1 extra=$2 d=$work/n$3
  command -v strace >/dev/null || { echo -; return; }
  strace -f -qq -z -e trace=execve -o "$work/strace" "$b" build $extra -q --cache-dir "$d/cache" \
    --config "$d/proj/rtcdoc.toml" -o "$d/out" -f json >/dev/null 2>&1 || true
  grep -c 'execve("[^"]*/git"' "$work/strace" || true
}

# The binaries measured: the baseline (if any) and this one, run in alternation (run 1 of
# each, then run 2 of each, …) so that the load of a shared machine falls on both alike.
names=(); bins=(); extras=()
if [ -n "${BASELINE:-}" ]; then names+=(baseline); bins+=("$BASELINE"); extras+=(""); fi
names+=(this); bins+=("$bin"); extras+=("${JOBS:+--jobs $JOBS}")

echo "| sources | binary | cold s | warm s | one dir s | warm/one dir | cold/warm | git processes (warm) | warm peak RSS MB |"
echo "|---|---|---|---|---|---|---|---|---|"
for n in "${counts[@]}"; do
  generate "$n"
  declare -A all=() git=()
  for k in $(seq "$runs"); do
    for i in "${!bins[@]}"; do
      all[$i]+="$(once "${bins[$i]}" "${extras[$i]}" "$n")"$'\n'
      # Counted once, on the cache and lock this binary just left.
      [ "$k" = 1 ] && git[$i]=$(gits "${bins[$i]}" "${extras[$i]}" "$n")
    done
  done
  for i in "${!bins[@]}"; do
    g=${git[$i]}
    col() { printf '%s' "${all[$i]}" | awk -v k="$1" 'NF { print $k }' | median; }
    c=$(col 1) w=$(col 2) o=$(col 3) r=$(col 4)
    awk -v n="$n" -v b="${names[$i]}" -v c="$c" -v w="$w" -v o="$o" -v g="$g" -v r="$r" \
      'BEGIN { printf "| %s | %s | %.2f | %.2f | %.2f | %.1f× | %.1f× | %s | %.1f |\n", n, b, c, w, o, w / o, c / w, g, r / 1024 }'
  done
  unset all git
done
