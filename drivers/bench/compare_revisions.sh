#!/usr/bin/env bash
# Side-by-side speed of two builds of picdem on one case: a base git revision (default 4272e69,
# the speed issue's baseline) built next to the current tree, both run in alternation on the same
# machine (so that its noise hits both alike), with the wall time of each run, the ratio, and the
# figures that show both ran the same physics (steps, pressure iterations, fluid volume change).
#
# usage: drivers/bench/compare_revisions.sh [--base REV] [--ranks N] [--repeat K]
#            [--case FILE] [--keep DIR] [-- picdem arguments, e.g. --set time/end=0.3]
# Default case: cases/dam_break_cylinders_6_layers at its own resolution (h = 0.5 mm) to 0.3 s,
# output and checkpoints off. Builds go to $PICDEM_BENCH_DIR (default /tmp/picdem-bench).
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
base=4272e69 ranks=2 repeat=1 case_file=$top/cases/dam_break_cylinders_6_layers/case.yaml keep=""
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --base) base=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --case) case_file=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "compare_revisions.sh: unknown argument '$1' (see the header of $0)" >&2; exit 2 ;;
  esac
done
[ ${#extra[@]} -gt 0 ] || extra=(--set time/end=0.3)
work=${PICDEM_BENCH_DIR:-/tmp/picdem-bench}
rev=$(git -C "$top" rev-parse --short "$base")
base_src=$work/base-$rev
mkdir -p "$work"

# The base revision's sources (git archive: no worktree left behind) and its build.
if [ ! -x "$base_src/build/drivers/picdem" ]; then
  rm -rf "$base_src" && mkdir -p "$base_src"
  git -C "$top" archive "$rev" | tar -x -C "$base_src"
  echo "building base $rev in $base_src/build"
  PICDEM_BUILD_DIR=$base_src/build bash "$base_src/drivers/scripts/build.sh" > "$work/build-$rev.log" 2>&1 \
    || { tail -n 30 "$work/build-$rev.log"; exit 1; }
fi
echo "building the current tree ($(git -C "$top" describe --always --dirty))"
bash "$top/drivers/scripts/build.sh" > "$work/build-current.log" 2>&1 \
  || { tail -n 30 "$work/build-current.log"; exit 1; }

mpiexec=(mpirun --oversubscribe -n "$ranks")
[ "$(id -u)" -eq 0 ] && mpiexec+=(--allow-run-as-root)
quiet=(--set output/paraview=false --set output/png=false --set checkpoint/at_end=false)

# run NAME BINARY K: one timed run; prints "wall_seconds" and leaves its output in $work/NAME-K
run() {
  local out=$work/$1-$3
  rm -rf "$out"
  local t0 t1
  t0=$(date +%s.%N)
  "${mpiexec[@]}" "$2" "$case_file" --output "$out" "${quiet[@]}" "${extra[@]}" \
    > "$out.log" 2>&1 || { echo "$1 run $3 failed:"; tail -n 20 "$out.log"; exit 1; }
  t1=$(date +%s.%N)
  python3 -c "print(f'{$t1 - $t0:.2f}')"
}

declare -a t_base t_cur
for k in $(seq 1 "$repeat"); do
  t_base+=("$(run base "$base_src/build/drivers/picdem" "$k")")
  t_cur+=("$(run current "$top/build/drivers/picdem" "$k")")
  echo "round $k: base $rev ${t_base[-1]} s, current ${t_cur[-1]} s"
done

python3 - "$work" "$repeat" "$rev" "${t_base[*]}" "${t_cur[*]}" <<'PY'
import csv, statistics, sys
work, repeat, rev = sys.argv[1], int(sys.argv[2]), sys.argv[3]
tb = [float(v) for v in sys.argv[4].split()]
tc = [float(v) for v in sys.argv[5].split()]

def figures(name):
    rows = list(csv.DictReader(open(f"{work}/{name}-{repeat}/timeseries.csv")))
    t_end = float(rows[-1]["t"])
    its = [float(r["ppe_iterations"]) for r in rows]
    v0, v1 = float(rows[0]["fluid_volume"]), float(rows[-1]["fluid_volume"])
    dv = 100.0 * (v1 - v0) / v0 if v0 > 0 else 0.0
    return t_end, len(rows), sum(its) / len(its), dv

print()
print(f"{'build':<14}{'median wall s':>14}{'wall s / sim s':>16}{'steps':>8}{'PPE its/step':>14}"
      f"{'volume change %':>17}")
for name, times in (("base " + rev, tb), ("current", tc)):
    t_end, steps, its, dv = figures(name.split()[0])
    med = statistics.median(times)
    print(f"{name:<14}{med:>14.2f}{med / t_end:>16.1f}{steps:>8d}{its:>14.2f}{dv:>17.2f}")
print(f"\nspeed-up current vs base {rev}: {statistics.median(tb) / statistics.median(tc):.2f}x "
      f"(median of {repeat} alternated run(s))")
PY
echo "phase timers of the last runs: $work/base-$repeat/timers.txt, $work/current-$repeat/timers.txt"
if [ -n "$keep" ]; then mkdir -p "$keep" && cp -r "$work/base-$repeat" "$work/current-$repeat" "$keep/"; fi
