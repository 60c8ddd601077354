#!/usr/bin/env bash
# Where 2 ranks lose against 1: runs the same build on 1 and on 2 ranks in alternation (ROUNDS
# rounds) and prints, for the step's top-level phases (timers.txt), the 1-rank time, the 2-rank
# time on the fastest and the slowest rank (TimeMonitor's min and max over the ranks), the
# speed-up of the phase (1 rank / slowest rank) and its loss: slowest 2-rank time - 1-rank time / 2,
# the seconds the phase costs beyond a perfect halving. "rest" is the wall time outside the phases
# (setup, seeding, the time step, rebalancing, diagnostics). Medians over the rounds.
#
# With BASE=<another picdem executable> (e.g. a build of an earlier revision) every round runs
# base 1 rank, base 2 ranks, then PICDEM 1 rank, 2 ranks, and a table is printed for each build.
#
# usage: [BASE=exe] drivers/bench/ranks/phase_split.sh [PICDEM] [ROUNDS] [END] [CASE] [-- --set ...]
set -euo pipefail
bench_name=phase_split default_end=0.03
source "$(dirname "$0")/bench_args.sh"
phases=("geometry" "transfer: mark cells" "transfer: particles to grid" "forces"
        "contact prediction" "pressure" "project" "solids" "transfer: grid to particles"
        "density correction" "advect")
builds=(cur)
[ -n "${BASE:-}" ] && builds=(base cur)
declare -A exe=([cur]=$picdem [base]=${BASE:-})

# run NAME RANKS EXE: one run, its wall seconds in NAME.wall
run() {
  local dir=$work/$1 t0 t1
  t0=$(date +%s.%N)
  "${mpi[@]}" -n "$2" "$3" "$case_file" "${common[@]}" -o "$dir" > "$dir.log" 2>&1 ||
    { tail -20 "$dir.log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f\n", b - a }' > "$dir.wall"
}

# field FILE PHASE COLUMN: a phase's seconds from timers.txt (column 1: min or the 1-rank time,
# 3: max over the ranks)
field() {
  awk -v name="picdem: $2" -v col="$3" '
    index($0, name " ") == 1 {
      rest = substr($0, length(name) + 1); gsub(/\([0-9]+\)/, "", rest); split(rest, v, " ")
      print (v[col] == "" ? v[1] : v[col]); found = 1 }
    END { if (!found) print 0 }' "$1"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "case $case_file, t = 0 to $end s, $rounds rounds, OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-unset}"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$rounds"); do
  for b in "${builds[@]}"; do
    run "${b}_r${r}_n1" 1 "${exe[$b]}"
    run "${b}_r${r}_n2" 2 "${exe[$b]}"
    echo "round $r, $b: 1 rank $(cat "$work/${b}_r${r}_n1.wall") s, 2 ranks $(cat "$work/${b}_r${r}_n2.wall") s"
  done
done
row() {  # row NAME V1... (rounds values of 1 rank, then min, then max)
  local name=$1; shift
  local a b c
  a=$(median "${@:1:$rounds}") b=$(median "${@:$((rounds + 1)):$rounds}")
  c=$(median "${@:$((2 * rounds + 1)):$rounds}")
  awk -v n="$name" -v a="$a" -v b="$b" -v c="$c" 'BEGIN {
    printf "%-30s %9.3f %9.3f %9.3f %7.2fx %9.3f\n", n, a, b, c, (c > 0 ? a / c : 0), c - a / 2 }'
}
for b in "${builds[@]}"; do
  echo "build $b: ${exe[$b]}"
  printf '%-30s %9s %9s %9s %8s %9s\n' phase "1 rank" "2: min" "2: max" speedup "loss [s]"
  sum1=() sum2=()
  for r in $(seq "$rounds"); do sum1+=(0) sum2+=(0); done
  for ph in "${phases[@]}"; do
    v1=() vmin=() vmax=()
    for r in $(seq "$rounds"); do
      v1+=("$(field "$work/${b}_r${r}_n1/timers.txt" "$ph" 1)")
      vmin+=("$(field "$work/${b}_r${r}_n2/timers.txt" "$ph" 1)")
      vmax+=("$(field "$work/${b}_r${r}_n2/timers.txt" "$ph" 3)")
      sum1[r - 1]=$(awk -v s="${sum1[r - 1]}" -v x="${v1[-1]}" 'BEGIN { print s + x }')
      sum2[r - 1]=$(awk -v s="${sum2[r - 1]}" -v x="${vmax[-1]}" 'BEGIN { print s + x }')
    done
    row "$ph" "${v1[@]}" "${vmin[@]}" "${vmax[@]}"
  done
  w1=() w2=() rest1=() rest2=()
  for r in $(seq "$rounds"); do
    w1+=("$(cat "$work/${b}_r${r}_n1.wall")") w2+=("$(cat "$work/${b}_r${r}_n2.wall")")
    rest1+=("$(awk -v w="${w1[-1]}" -v s="${sum1[r - 1]}" 'BEGIN { print w - s }')")
    rest2+=("$(awk -v w="${w2[-1]}" -v s="${sum2[r - 1]}" 'BEGIN { print w - s }')")
  done
  row "rest (wall - phases)" "${rest1[@]}" "${rest2[@]}" "${rest2[@]}"
  row "whole run (wall)" "${w1[@]}" "${w2[@]}" "${w2[@]}"
  for t in "setup" "step" "halo: forward" "halo: reverse add"; do
    grep -h "picdem: $t  " "$work/${b}_r1_n2/timers.txt" | sed "s/^/  2 ranks, round 1: /" || true
  done
done
grep -h "cut lines" "$work/cur_r1_n2.log" | head -5
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg); runs in $work"
