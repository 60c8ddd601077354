#!/usr/bin/env bash
# Where 2 ranks wait: alternates 1-rank and 2-rank runs of one build with mpi_wait.so preloaded
# (drivers/bench/ranks/mpi_wait.cpp: each rank's seconds in every top-level phase and in MPI calls
# within it) and splits each phase's loss against a perfect halving, loss = T2 - T1 / 2, into
#   extra work  = mean over the ranks of (phase - MPI seconds) - T1 / 2 (work that does not halve),
#   imbalance   = max over the ranks of that compute - its mean,
#   waiting     = T2 - max compute (MPI latency and the time slices of the other rank),
# T2 the phase's seconds on the slowest rank, T1 on 1 rank. Medians over the rounds.
#
# usage: drivers/bench/ranks/wait_split.sh [PICDEM] [ROUNDS] [END] [CASE] [-- --set ...]
set -euo pipefail
bench_name=wait_split default_end=0.03
source "$(dirname "$0")/bench_args.sh"
here=$(cd "$(dirname "$0")" && pwd)
lib=$work/mpi_wait.so
mpicxx -O2 -DOMPI_SKIP_MPICXX -shared -fPIC -I/usr/include/trilinos -o "$lib" "$here/mpi_wait.cpp" -ldl

run() {  # run NAME RANKS
  local dir=$work/$1 t0 t1
  t0=$(date +%s.%N)
  "${mpi[@]}" -x LD_PRELOAD="$lib" -x MPI_WAIT_FILE="$dir.wait" -n "$2" "$picdem" "$case_file" \
    "${common[@]}" -o "$dir" > "$dir.log" 2>&1 || { tail -20 "$dir.log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f\n", b - a }' > "$dir.wall"
}

echo "case $case_file, t = 0 to $end s, $rounds rounds, extra: ${extra[*]:-none}," \
  "OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-unset}"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$rounds"); do
  run "r${r}_n1" 1
  run "r${r}_n2" 2
  echo "round $r: 1 rank $(cat "$work/r${r}_n1.wall") s, 2 ranks $(cat "$work/r${r}_n2.wall") s," \
    "load $(cut -d' ' -f1 /proc/loadavg)"
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg); runs in $work"
python3 - "$work" "$rounds" <<'PY'
import re, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
def read(path):  # {(rank, phase): (wall, mpi wall, cpu, mpi cpu)} of the top-level phases
    out = {}
    for line in open(path):
        m = re.match(r'(\d+) top "(.*)" (\S+) (\S+) \d+ (\S+) (\S+)', line)
        if m: out[(int(m[1]), m[2])] = tuple(float(m[i]) for i in range(3, 7))
    return out
zero = (0.0, 0.0, 0.0, 0.0)
rows = {}
for r in range(1, rounds + 1):
    one, two = read(f"{work}/r{r}_n1.wait"), read(f"{work}/r{r}_n2.wait")
    for ph in {p for _, p in one} | {p for _, p in two}:
        a = one.get((0, ph), zero)
        s = [two.get((k, ph), zero) for k in (0, 1)]
        t1, t2 = a[0], max(x[0] for x in s)
        c1 = a[2] - a[3]                      # 1 rank: compute CPU
        c = [x[2] - x[3] for x in s]          # 2 ranks: compute CPU per rank
        cw = [x[0] - x[1] for x in s]         # 2 ranks: wall outside MPI per rank
        mc = statistics.mean(c)
        rows.setdefault(ph, []).append((t1, t2, c1, c[0], c[1], mc - c1 / 2, max(c) - mc,
                                        t2 - max(cw), s[0][1], s[1][1]))
med = statistics.median
heads = ["1r wall", "2r wall", "1r cpu", "cpu r0", "cpu r1", "extra", "imbal.", "wait",
         "MPI r0", "MPI r1"]
print("wall: seconds of the phase (2 ranks: the slower rank); cpu: compute CPU seconds (phase less"
      " its MPI calls); extra = mean 2-rank compute - 1-rank compute / 2; imbal. = max - mean"
      " compute; wait = 2-rank wall - the larger wall outside MPI; MPI rN: wall seconds in MPI")
print(f"{'phase':30s} " + " ".join(f"{h:>8s}" for h in heads))
for ph in sorted(rows, key=lambda p: -med([x[1] for x in rows[p]])):
    v = rows[ph]
    cols = [med([x[i] for x in v]) for i in range(len(heads))]
    print(f"{ph[:30]:30s} " + " ".join(f"{c:8.3f}" for c in cols))
print("('step (whole)' holds every phase of the steps; 'step, outside its phases' only MPI time;"
      " '(none)': outside every picdem timer. Seconds summed over the run, medians of the rounds.)")
PY
