#!/usr/bin/env bash
# Number and size of the MPI messages per coupled step on 1 to 8 ranks (oversubscribed): each
# rank count runs the case for A and for B steps with mpi_counts.so preloaded (PMPI counters of
# point-to-point sends and collective calls); (B - A) steps' difference per step is printed,
# mean and largest over the ranks.
#
# usage: drivers/bench/ranks/messages_per_step.sh [PICDEM] [CASE] [A] [B] [RANKS...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
picdem=${1:-build/drivers/picdem}
case_file=${2:-cases/dam_break_cylinders_6_layers/case.yaml}
a=${3:-4}
b=${4:-12}
shift $(($# < 4 ? $# : 4))
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2 4 8)
work=$(mktemp -d /tmp/picdem_messages.XXXXXX)
mpicc -O2 -shared -fPIC -o "$work/mpi_counts.so" "$here/mpi_counts.c"
mpi=(mpirun --oversubscribe)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
args=(--set output/paraview=false --set output/png=false --set checkpoint/at_end=false
      --set time/end=10)

count() {  # ranks steps -> counts file
  local f=$work/counts_$1_$2.txt
  rm -f "$f"
  "${mpi[@]}" -x "LD_PRELOAD=$work/mpi_counts.so" -x "MPI_COUNTS_FILE=$f" -n "$1" "$picdem" \
    "$case_file" "${args[@]}" --max-steps "$2" -o "$work/run_$1_$2" > "$work/run_$1_$2.log" 2>&1
  echo "$f"
}

echo "case $case_file, steps $a to $b; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%5s | %22s | %22s | %22s | %22s\n' ranks "p2p msgs/step mean,max" \
  "p2p KiB/step mean,max" "collectives/step mean" "coll. KiB/step mean"
for n in "${ranks[@]}"; do
  fa=$(count "$n" "$a")
  fb=$(count "$n" "$b")
  join <(sort -n "$fa") <(sort -n "$fb") | awk -v s=$((b - a)) -v n="$n" '
    { m = ($6 - $2) / s; k = ($7 - $3) / s / 1024; c = ($8 - $4) / s; cb = ($9 - $5) / s / 1024
      sm += m; sk += k; sc += c; scb += cb
      if (m > mm) mm = m
      if (k > mk) mk = k }
    END { printf "%5d | %10.0f %11.0f | %10.1f %11.1f | %22.0f | %22.1f\n", n, sm / NR, mm,
          sk / NR, mk, sc / NR, scb / NR }'
  grep -h "cut lines" "$work/run_${n}_$b.log" | head -1 || true
done
echo "runs in $work"
