#!/usr/bin/env bash
# Every file in bad_cases/ must stop `picdem --check` (and a few a real launch) with exit code 2 and the message in its
# .expect file, on the given number of ranks (never a crash or a hang).
# usage: check_bad_cases.sh PICDEM RANKS MPIEXEC...
set -u
# When a rank exits non-zero, mpirun sends SIGTERM to the rest of the job and waits this many seconds before
# SIGKILL; every launch here exits non-zero on purpose, and the default 1 s wait (about 2 s per launch in all)
# was two thirds of this test's time. The ranks are killed either way, so nothing the test checks changes.
export OMPI_MCA_odls_base_sigkill_timeout=0
picdem=$1 ranks=$2
shift 2
dir=$(cd "$(dirname "$0")" && pwd)/bad_cases
passed=0 failed=0
want=2  # the exit code check() expects: 2 (input refused), 3 for the runs that stop
check() {  # name, expected text, args...
  local name=$1 expect=$2
  shift 2
  out=$(timeout 120 "$@" 2>&1)
  code=$?
  if [ "$code" -ne "$want" ]; then
    echo "FAIL $name: exit code $code, expected $want"; echo "$out" | head -5; failed=$((failed + 1))
  elif ! grep -qF -- "$expect" <<< "$out"; then
    echo "FAIL $name: message lacks: $expect"; echo "$out" | head -5; failed=$((failed + 1))
  else
    passed=$((passed + 1))
  fi
}
for f in "$dir"/*.yaml; do
  name=$(basename "$f" .yaml)
  check "$name" "$(cat "$dir/$name.expect")" "$@" -n "$ranks" "$picdem" --check "$f"
done
# A real launch stops the same way, before anything runs.
out_dir=$(mktemp -d)
for name in disks_overlap disk_outside_tank disk_in_obstacle cell_size_absurd muelu_bad_smoother \
  muelu_smoother_param_bad_value muelu_coarse_param_unknown \
  belos_wrong_type; do
  check "run_$name" "$(cat "$dir/$name.expect")" "$@" -n "$ranks" "$picdem" "$dir/$name.yaml" \
    --output "$out_dir/$name" --max-steps 1
done
# Cases that pass --check but cannot run stop at their first steps with exit code 3 and a message
# naming what to change (found by running mutated case files for a few steps), never a crash.
want=3
for f in "$dir"/../failing_runs/*.yaml; do
  name=$(basename "$f" .yaml)
  check "run_$name" "$(cat "${f%.yaml}.expect")" "$@" -n "$ranks" "$picdem" "$f" \
    --output "$out_dir/$name" --max-steps 3 --set output/png=false --set output/paraview=false
done
want=2
# Memory the estimate allows (run/memory_limit_gb raised) but the process cannot get (ulimit -v):
# std::bad_alloc is reported with the process size and the keys to change (exit code 4).
if [ "$ranks" -eq 1 ]; then
  out=$( (ulimit -v 1500000; timeout 120 "$picdem" "$dir/../good_case.yaml" --output "$out_dir/oom" \
    --max-steps 1 --set grid/cell_size=0.00004 --set "water/column/x=[0.0,0.2]" \
    --set "water/column/z=[0.0,0.1]" --set run/memory_limit_gb=100 --set output/png=false \
    --set output/paraview=false) 2>&1)
  code=$?
  if [ "$code" -eq 4 ] && grep -q "out of memory (std::bad_alloc), process size VmSize" <<< "$out" \
    && grep -q "make grid/cell_size larger" <<< "$out"; then
    passed=$((passed + 1))
  else
    echo "FAIL bad_alloc: exit code $code"; echo "$out" | head -5; failed=$((failed + 1))
  fi
fi
rm -rf "$out_dir"
check missing_file "cannot open the case file" "$@" -n "$ranks" "$picdem" --check "$dir/no_such_file.yaml"
check bad_override "key 'fluid/density' = -1 is not allowed: must be > 0" \
  "$@" -n "$ranks" "$picdem" --check "$dir/../good_case.yaml" --set fluid/density=-1
check unknown_override "unknown key 'grid/cellsize'" \
  "$@" -n "$ranks" "$picdem" --check "$dir/../good_case.yaml" --set grid/cellsize=0.1
check directory_without_case "a directory, not a case file, and it holds no case.yaml" \
  "$@" -n "$ranks" "$picdem" --check "$dir"
check unknown_option "unknown option --frobnicate" "$@" -n "$ranks" "$picdem" --frobnicate
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
