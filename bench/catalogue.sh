#!/usr/bin/env bash
# Catalogue-scale benchmark: rtcdoc vs Hugo vs the file-creation floor (cp -r).
#
# usage: bench/catalogue.sh [N ...]        (default: 100 1000 10000 30000)
#        RUNS=5 bench/catalogue.sh 10000    (runs per measurement, Hugo too; default 3)
#        BENCH_DIR=/dev/shm/b …             (where catalogues and outputs go; default /tmp)
#        IDL=0 bench/catalogue.sh …         (catalogues without their generated IDL files)
#        SHAPE=corpus bench/catalogue.sh …  (profiles cloned from the real-world corpus instead of
#                                            the examples; CORPUS=DIR, default ../shared/corpus/rtc-xml)
#        OPENRTM_IDL=DIR SHAPE=corpus …     (with the *.idl of an OpenRTM installation's IDL directory)
#        BASELINE=/path/to/rtcdoc …         (also an older binary's HTML build, in the same pairs)
#        BIN=/path/to/rtcdoc …              (measure this binary; default: cargo build --release)
#        HUGO=0 bench/catalogue.sh 30000    (without Hugo: it needs about 0.5 GB per 1,000 pages)
#        HUGO_MAX=N …                       (Hugo only up to N profiles; default 10000, so that the
#                                            30,000 point measures rtcdoc and the floor alone)
#
# The catalogues carry IDL (bench/gen_catalogue.py: one file of structs, enums, sequences,
# exceptions and interfaces per group of about forty components, named by the ports' idlFile),
# so every build below reads it and renders the definitions on the type and interface pages.
#
# For each N it generates a synthetic catalogue (bench/gen_catalogue.py), then measures with
# /usr/bin/time -v, for each output format: wall time, profiles/s, files/s and peak RSS;
# `rtcdoc check`; Hugo rendering rtcdoc's own Markdown output with a minimal layout; and
# the floor: reading every input file (cat) and `cp -r` of rtcdoc's HTML output (creating that
# many files on this disk), as one command.
# Each measurement (rtcdoc, cp and Hugo) is run RUNS times (the HTML build and its cp -r in
# alternation, so that the ratio of the two is also reported per pair) and the median wall time is
# reported (RSS: the largest of the runs); the file system is synced before every run, so a run
# does not pay for the previous run's writes. Old outputs are moved aside, not deleted, until
# the end: ext4 avoids reusing inodes freed in the last seconds and scans further for each new
# file, which made a run right after deleting 14,000 files up to 4× slower (cp -r included).
# (On a tmpfs, which has no such delay, old outputs are deleted at once: kept, they fill memory.)
# The old outputs are deleted when the script ends, and the next run waits until five minutes
# have passed since (SETTLE_SECONDS).
# Installs hugo and GNU time with apt-get when missing (root only). Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
sizes=("$@")
runs=${RUNS:-3}
[ ${#sizes[@]} -eq 0 ] && sizes=(100 1000 10000 30000)
work=${BENCH_DIR:-/tmp/rtcdoc-bench}
mkdir -p "$work"
trash="$work/trash"
# Deleting many files leaves ext4 slow to create new ones for minutes (a run started two minutes
# after the previous run's clean-up measured every rtcdoc build and the cp -r floor 1.7× slower):
# the time of each clean-up is recorded, and a run starts only five minutes after the last one.
settle=${SETTLE_SECONDS:-300}
stamp_file="$work/.last-deletion"
clean_up() { rm -rf "$trash"; date +%s >"$stamp_file"; }
if [ -e "$trash" ]; then clean_up; fi
if [ -e "$stamp_file" ]; then
  wait_s=$(( $(cat "$stamp_file") + settle - $(date +%s) ))
  if [ "$wait_s" -gt 0 ]; then
    echo "waiting ${wait_s}s for the disk to settle after the last clean-up (SETTLE_SECONDS=0 skips)" >&2
    sleep "$wait_s"
  fi
fi
mkdir -p "$trash"
trap clean_up EXIT
# set_aside DIR: moves DIR out of the way (a rename), to be deleted when the script ends. On a
# tmpfs it is deleted at once instead: there the trees set aside stay in memory (at 30,000
# profiles they filled the machine's memory and the kernel killed the Doxygen build), and a
# tmpfs has no inode reuse to wait for.
on_tmpfs=0
if [ "$(stat -f -c %T "$work" 2>/dev/null)" = tmpfs ]; then on_tmpfs=1; fi
set_aside() {
  if [ ! -e "$1" ]; then return; fi
  if [ "$on_tmpfs" = 1 ]; then rm -rf "$1"; else mv "$1" "$(mktemp -d "$trash/old.XXXXXX")/"; fi
}

if ! command -v hugo >/dev/null || [ ! -x /usr/bin/time ]; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq hugo time >/dev/null
  fi
fi
if [ -n "${BIN:-}" ]; then
  bin=$(realpath "$BIN")
else
  cargo build --release --quiet
  bin=$PWD/target/release/rtcdoc
fi

# measure CMD...: runs CMD under /usr/bin/time, prints "seconds rss_mb"
measure() {
  local log="$work/time.log"
  sync
  /usr/bin/time -v "$@" >"$work/cmd.out" 2>"$log" || {
    # `rtcdoc check` exits 1 when a profile has an error (the corpus has some): still measured.
    if [ "${2:-}" != check ] || ! grep -q 'Exit status: 1$' "$log"; then
      echo "failed: $*" >&2; tail -5 "$log" >&2; return 1
    fi
  }
  local wall rss
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$log")
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$log")
  python3 - "$wall" "$rss" <<'PY'
import sys
w, rss = sys.argv[1], int(sys.argv[2])
parts = [float(p) for p in w.split(":")]
s = parts[-1] + (parts[-2] * 60 if len(parts) > 1 else 0) + (parts[-3] * 3600 if len(parts) > 2 else 0)
print(f"{s:.2f} {rss/1024:.0f}")
PY
}

# measure_runs CLEAN CMD...: RUNS times `set_aside CLEAN; measure CMD`; prints the median wall time
# and the largest RSS.
measure_runs() {
  local clean=$1; shift
  local results=()
  for ((r = 0; r < runs; r++)); do
    set_aside "$clean"
    results+=("$(measure "$@")")
  done
  printf '%s\n' "${results[@]}" | python3 -c '
import sys
rows = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
walls = sorted(r[0] for r in rows)
print(f"{walls[len(walls) // 2]:.2f} {max(r[1] for r in rows):.0f}")'
}

files_in() { find "$1" -type f | wc -l; }

echo "| N | what | wall s | profiles/s | files | files/s | peak RSS MB |"
echo "|---|---|---:|---:|---:|---:|---:|"
declare -A html_time
for n in "${sizes[@]}"; do
  gen_flags=()
  suffix=""
  inputs=(bench/gen_catalogue.py examples)
  if [ "${SHAPE:-example}" = corpus ]; then
    corpus=${CORPUS:-$PWD/../shared/corpus/rtc-xml}
    gen_flags=(--shape corpus --corpus "$corpus")
    inputs=(bench/gen_catalogue.py "$corpus")
    suffix="-corpus"
    if [ -n "${OPENRTM_IDL:-}" ]; then
      gen_flags+=(--openrtm-idl "$OPENRTM_IDL"); inputs+=("$OPENRTM_IDL"); suffix="-corpus-idl"
    fi
  elif [ "${IDL:-1}" = 0 ]; then gen_flags=(--no-idl); suffix="-noidl"; fi
  src="$work/cat-$n$suffix"
  # Generated once per N and kept (deterministic; regenerated when the examples, the corpus or
  # the generator change), so that no run follows the deletion of 10,000 files.
  stamp=$(find "${inputs[@]}" -type f | sort | xargs cat | sha1sum | cut -c1-16)
  if [ "$(cat "$src/.stamp" 2>/dev/null)" != "$stamp" ]; then
    set_aside "$src"
    python3 bench/gen_catalogue.py "$n" "$src" "${gen_flags[@]}" >/dev/null
    echo "$stamp" >"$src/.stamp"
  fi
  # The HTML build and the cp -r floor of its output run in alternation, so that both see the
  # same state of the disk (ext4 here made the same cp -r take 0.47 s in one run and 1.05 s in
  # another): medians of each, and the median of the per-pair ratios.
  # The floor reads every input file and copies the output tree, in one command.
  pairs=()
  base_runs=()
  for ((r = 0; r < runs; r++)); do
    if [ -n "${BASELINE:-}" ]; then
      set_aside "$work/out-$n-html-base"
      base_runs+=("$(measure "$BASELINE" build "$src" -f html -o "$work/out-$n-html-base" -q)")
    fi
    set_aside "$work/out-$n-html"
    read -r a rss_a < <(measure "$bin" build "$src" -f html -o "$work/out-$n-html" -q)
    set_aside "$work/copy-$n"
    read -r b rss_b < <(measure sh -c 'find "$1" -type f -exec cat {} + >/dev/null && cp -r "$2" "$3"' floor "$src" "$work/out-$n-html" "$work/copy-$n")
    pairs+=("$a $b $rss_a $rss_b")
  done
  if [ -n "${BASELINE:-}" ]; then
    read -r bs brss < <(printf '%s\n' "${base_runs[@]}" | python3 -c '
import sys
rows = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
print(f"{sorted(r[0] for r in rows)[len(rows) // 2]:.2f} {max(r[1] for r in rows):.0f}")')
    f=$(files_in "$work/out-$n-html-base")
    python3 -c "print(f'| $n | baseline build --format html | $bs | {$n/max($bs,0.001):.0f} | $f | {$f/max($bs,0.001):.0f} | $brss |')"
  fi
  read -r s floor html_rss cp_rss paired runs_txt < <(printf '%s\n' "${pairs[@]}" | python3 -c '
import sys
rows = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
med = lambda v: sorted(v)[len(v) // 2]
ratios = [a / max(b, 0.001) for a, b, _, _ in rows]
runs = ",".join(f"{a:.2f}/{b:.2f}" for a, b, _, _ in rows)
print(f"{med([r[0] for r in rows]):.2f} {med([r[1] for r in rows]):.2f} {max(r[2] for r in rows):.0f} {max(r[3] for r in rows):.0f} {med(ratios):.2f} {runs}")')
  html_time[$n]=$s
  f=$(files_in "$work/out-$n-html")
  python3 -c "print(f'| $n | rtcdoc build --format html | $s | {$n/max($s,0.001):.0f} | $f | {$f/max($s,0.001):.0f} | $html_rss |')"
  for fmt in markdown doxygen json; do
    out="$work/out-$n-$fmt"
    read -r s rss < <(measure_runs "$out" "$bin" build "$src" -f "$fmt" -o "$out" -q)
    f=$(files_in "$out")
    python3 -c "print(f'| $n | rtcdoc build --format $fmt | $s | {$n/max($s,0.001):.0f} | $f | {$f/max($s,0.001):.0f} | $rss |')"
  done
  read -r s rss < <(measure_runs "$work/none" "$bin" check "$src" -q || true)
  python3 -c "print(f'| $n | rtcdoc check | $s | {$n/max($s,0.001):.0f} | - | - | $rss |')"

  # The floor: copying rtcdoc's own HTML tree (measured above, alternating with the builds).
  f=$(files_in "$work/copy-$n")
  python3 -c "print(f'| $n | read inputs + cp -r of the HTML output (floor) | $floor | - | $f | {$f/max($floor,0.001):.0f} | $cp_rss |')"
  echo "|   | paired: rtcdoc HTML time ÷ floor, median of the per-run ratios = $paired (HTML/cp s: $runs_txt) | | | | | |"

  # Hugo on rtcdoc's Markdown output, minimal layout.
  if [ "${HUGO:-1}" != 0 ] && [ "$n" -le "${HUGO_MAX:-10000}" ] && command -v hugo >/dev/null; then
    site="$work/hugo-$n"
    set_aside "$site"
    mkdir -p "$site/layouts/_default"
    cp -r "$work/out-$n-markdown" "$site/content"
    rm -f "$site/content/.rtcdoc-output" "$site/content/README.md"
    # A content/index.md would make the whole folder one leaf bundle; Hugo's home page is _index.md.
    mv "$site/content/index.md" "$site/content/_index.md"
    printf 'baseURL = "http://localhost/"\ntitle = "bench"\ndisableKinds = ["taxonomy", "term", "RSS"]\n[markup.goldmark.renderer]\nunsafe = true\n' >"$site/hugo.toml"
    printf '<!DOCTYPE html><html><head><title>{{ .Title }}</title></head><body>{{ .Content }}</body></html>\n' >"$site/layouts/_default/single.html"
    printf '<!DOCTYPE html><html><head><title>{{ .Title }}</title></head><body>{{ .Content }}</body></html>\n' >"$site/layouts/_default/list.html"
    read -r s rss < <(measure_runs "$site/public" hugo --source "$site" --quiet --destination "$site/public")
    f=$(find "$site/public" -name '*.html' | wc -l)
    python3 -c "print(f'| $n | hugo on the Markdown output | $s | {$n/max($s,0.001):.0f} | $f | {$f/max($s,0.001):.0f} | $rss |')"
    hugo_time=$s
    hugo_pages=$f
    rt_pages=$(find "$work/out-$n-html" -name '*.html' | wc -l)
    python3 -c "h=$hugo_pages/max($hugo_time,0.001); r=$rt_pages/max(${html_time[$n]},0.001); print(f'|   | ratio: rtcdoc HTML pages/s ÷ hugo pages/s = {r/h:.1f}× ; rtcdoc HTML time ÷ floor = {${html_time[$n]}/max($floor,0.001):.2f} | | | | | |')"
  fi
done
if [ ${#sizes[@]} -ge 2 ]; then
  a=${sizes[-2]}; b=${sizes[-1]}
  python3 -c "print(f'\nHTML time ratio N=$b / N=$a: {${html_time[$b]}/max(${html_time[$a]},0.001):.2f} (linear would be {$b/$a:.0f})')"
fi
