#!/usr/bin/env bash
# Build time against run time of the two optimised profiles: `release` (what `cargo run
# --release`, `cargo build --release` and `cargo install` use; quick to compile) and `dist`
# (inherits release: fat LTO in one code unit; what the wheels and shipped binaries use).
#
# usage: bench/build_profiles.sh [N]          (catalogue size for the run times; default 3000)
#        RUNS=5 bench/build_profiles.sh       (runs per run-time measurement, median; default 5)
#        BENCH_DIR=/dev/shm/b …               (where the target directories, the catalogue and
#                                              the outputs go; default /tmp/rtcdoc-build-profiles)
#        JOBS=2 …                             (cargo's -j; default: every core)
#
# Each profile is built from clean (its own empty target directory, so every dependency is
# compiled too, as on a fresh clone) with `cargo build --locked`, under /usr/bin/time: wall time
# and CPU time (user + system). Then both binaries build the same inputs, in alternation, RUNS
# times each: the bundled examples (`build examples -f html`) and a generated catalogue of N
# profiles with IDL (bench/gen_catalogue.py, `build -f html`); the median wall time of each.
# The project's own target/ is not touched. Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-3000}
runs=${RUNS:-5}
work=${BENCH_DIR:-/tmp/rtcdoc-build-profiles}
jobs=()
[ -n "${JOBS:-}" ] && jobs=(-j "$JOBS")
mkdir -p "$work"
[ -x /usr/bin/time ] || { echo "build_profiles.sh: needs GNU time (/usr/bin/time; apt-get install time)" >&2; exit 1; }

# seconds WALL_CLOCK_TEXT: "m:ss.cc" or "h:mm:ss" → seconds.
seconds() {
  python3 -c '
import sys
p = [float(x) for x in sys.argv[1].split(":")]
print(f"{p[-1] + (p[-2] * 60 if len(p) > 1 else 0) + (p[-3] * 3600 if len(p) > 2 else 0):.2f}")' "$1"
}

# timed LOG CMD...: runs CMD under /usr/bin/time -v; prints "wall_s cpu_s".
timed() {
  local log=$1; shift
  /usr/bin/time -v "$@" >"$log.out" 2>"$log" || { echo "failed: $*" >&2; tail -20 "$log" >&2; return 1; }
  local wall user sys
  wall=$(seconds "$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$log")")
  user=$(awk -F': ' '/User time/ {print $2}' "$log")
  sys=$(awk -F': ' '/System time/ {print $2}' "$log")
  python3 -c "print(f'$wall {$user + $sys:.1f}')"
}

declare -A build_wall build_cpu bin
for profile in release dist; do
  target="$work/target-$profile"
  rm -rf "$target"
  sync
  read -r w c < <(CARGO_TARGET_DIR="$target" CARGO_INCREMENTAL=0 timed "$work/build-$profile.log" \
    cargo build --locked --quiet --profile "$profile" "${jobs[@]}")
  build_wall[$profile]=$w
  build_cpu[$profile]=$c
  bin[$profile]="$target/$profile/rtcdoc"
  echo "built $profile in ${w} s (CPU ${c} s)" >&2
done

cat_dir="$work/cat-$n"
stamp=$(find bench/gen_catalogue.py examples -type f | sort | xargs cat | sha1sum | cut -c1-16)
if [ "$(cat "$cat_dir/.stamp" 2>/dev/null)" != "$stamp" ]; then
  rm -rf "$cat_dir"
  python3 bench/gen_catalogue.py "$n" "$cat_dir" >/dev/null
  echo "$stamp" >"$cat_dir/.stamp"
fi

# run_times INPUT NAME: both binaries on INPUT, in alternation; sets run[profile,NAME] (median).
declare -A run
run_times() {
  local input=$1 name=$2
  declare -A got=([release]="" [dist]="")
  for ((r = 0; r < runs; r++)); do
    for profile in release dist; do
      local out="$work/out-$name-$profile"
      rm -rf "$out"
      sync
      read -r w _ < <(timed "$work/run.log" "${bin[$profile]}" build "$input" -f html -o "$out" -q)
      got[$profile]+="$w "
    done
  done
  for profile in release dist; do
    run[$profile,$name]=$(python3 -c '
import sys
v = sorted(float(x) for x in sys.argv[1:])
print(f"{v[len(v) // 2]:.3f}")' ${got[$profile]})
  done
}
run_times examples examples
run_times "$cat_dir" "cat$n"

echo "| profile | clean build, wall | clean build, CPU | examples (HTML) | $n generated profiles (HTML) | binary |"
echo "|---|---:|---:|---:|---:|---:|"
for profile in release dist; do
  size=$(wc -c <"${bin[$profile]}" | tr -d ' ')
  python3 -c "
w = ${build_wall[$profile]}
print(f'| \`$profile\` | {int(w // 60)} min {w % 60:04.1f} s | ${build_cpu[$profile]} s | ${run[$profile,examples]} s | ${run[$profile,cat$n]} s | {$size / 1048576:.1f} MiB |')"
done
python3 -c "
print()
print(f'dist ÷ release: clean build {${build_wall[dist]} / ${build_wall[release]}:.2f}×, run time on $n profiles {${run[dist,cat$n]} / ${run[release,cat$n]}:.3f}×, on the examples {${run[dist,examples]} / ${run[release,examples]}:.3f}×')
print('(median of $runs runs each, alternating; $(nproc) cores; $(date -u +%F))')"
