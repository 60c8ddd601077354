#!/usr/bin/env bash
# 1 rank against 2 ranks on the same build, side by side: the runs alternate (1 rank, 2 ranks
# with grid/decomposition=weighted, 2 ranks with grid/decomposition=uniform) so that the load of
# the machine falls on all three alike; prints each run's wall time and the median ratios.
#
# usage: drivers/bench/ranks/ranks_speedup.sh [PICDEM] [ROUNDS] [END] [CASE] [-- extra --set args]
#   PICDEM  the executable (default build/drivers/picdem)
#   ROUNDS  alternations (default 3)
#   END     simulated end time in seconds (default 0.05)
#   CASE    case file (default cases/dam_break_cylinders_6_layers/case.yaml)
set -euo pipefail
bench_name=ranks_speedup default_end=0.05
source "$(dirname "$0")/bench_args.sh"

# run NAME RANKS MODE -> prints the wall seconds of one run
run() {
  local dir=$work/$1 t0 t1
  t0=$(date +%s.%N)
  "${mpi[@]}" -n "$2" "$picdem" "$case_file" "${common[@]}" --set "grid/decomposition=$3" \
    -o "$dir" > "$dir.log" 2>&1 || { tail -20 "$dir.log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }'
}

echo "case $case_file, t = 0 to $end s, $rounds rounds; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-6s %12s %16s %16s\n' round "1 rank [s]" "2 weighted [s]" "2 uniform [s]"
one=() two=() uni=()
for r in $(seq "$rounds"); do
  a=$(run "r${r}_n1" 1 weighted)
  b=$(run "r${r}_n2w" 2 weighted)
  c=$(run "r${r}_n2u" 2 uniform)
  one+=("$a") two+=("$b") uni+=("$c")
  printf '%-6s %12s %16s %16s\n' "$r" "$a" "$b" "$c"
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
m1=$(median "${one[@]}") m2=$(median "${two[@]}") mu=$(median "${uni[@]}")
steps=$(tail -1 "$work/r1_n1/timeseries.csv" | cut -d, -f3)
echo "median: 1 rank $m1 s, 2 ranks weighted $m2 s, 2 ranks uniform $mu s ($steps steps)"
awk -v a="$m1" -v b="$m2" -v c="$mu" 'BEGIN { printf "speed-up of 2 ranks: weighted %.2fx, uniform %.2fx\n", a / b, a / c }'
grep -h "cut lines" "$work/r1_n2w.log" | head -5
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg); runs in $work"
