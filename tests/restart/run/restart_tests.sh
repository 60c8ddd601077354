#!/usr/bin/env bash
# Restart tests of the picdem executable (doc/restart.md). Each test runs in its own folder.
# usage: restart_tests.sh PICDEM SOURCE_DIR WORK_DIR PYTHON TEST [TEST ARGS] -- MPIEXEC...
#   TEST: bitwise N CASE | ranks N M | ranks_straddling N M | kill_during_write | sigterm | sigusr1 | bad_files | blow_up
#         | schedule | layout | extend | frames
set -u
picdem=$1 src=$2 work=$3 python=$4 test=$5
shift 5
targs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do targs+=("$1"); shift; done
shift
mpi=("$@")
cmp="$python $src/tests/restart/run/compare_checkpoints.py"
fail() { echo "FAIL: $*"; exit 1; }
ck() { printf '%s/checkpoints/checkpoint_%08d.h5' "$1" "$2"; }

# run N DIR ARGS...: picdem on N ranks (exit code checked by the caller).
run() {
  local n=$1 dir=$2
  shift 2
  timeout 300 "${mpi[@]}" -n "$n" "$picdem" "$@" -o "$dir" > "$dir.log" 2>&1
}
expect_ok() { [ "$1" -eq 0 ] || { tail -20 "$2.log"; fail "$2: exit code $1"; }; }

floating_disk=(cases/floating_disk/case.yaml --set grid/cell_size=0.002 --set output/png=false
               --set output/interval=0.005)
disks=(tests/restart/run/disks_in_water.yaml)
# the fall pipe at reduced resolution (three times its cell size), once cases/fall_pipe_continuous exists
fall_pipe() {
  local f=cases/fall_pipe_continuous/case.yaml
  local h
  h=$(sed -n 's/^ *cell_size: *\([0-9.eE+-]*\).*/\1/p' "$f" | head -1)
  echo "$f --set output/png=false --set grid/cell_size=$(awk "BEGIN{print 3*$h}")"
}
case_args() {  # name -> the case file and its overrides
  case $1 in
  floating_disk) echo "${floating_disk[@]}" ;;
  fall_pipe) fall_pipe ;;
  # the dam break in 3 column strips, their cut lines recomputed every 4 steps and taken at any gain
  # (grid/decomposition = weighted): the cuts follow the water before and after step 20
  rebalance)
    local r=(cases/dam_break/case.yaml --set grid/cell_size=0.004 --set output/png=false
             --set grid/rebalance_interval=4 --set grid/rebalance_gain=0 --set grid/ranks_x=3)
    echo "${r[@]}" ;;
  # the pressure rows a kept band (solver/pressure_structure fixed), chosen again at checkpoints
  disks_fixed) echo "${disks[@]} --set solver/pressure_structure=fixed --set solver/structure_margin=1" ;;
  *) echo "${disks[@]}" ;;
  esac
}

rm -rf "$work" && mkdir -p "$work" && cd "$src" || exit 1
W=$work

case $test in
bitwise)
  # Restart == continuous run, bitwise, on N ranks: every dataset of the state at the end, and the
  # output the restarted run continued (time series, solids, frame index) byte for byte.
  n=${targs[0]}
  read -r -a c <<< "$(case_args "${targs[1]}")"
  end=40 every=(--set checkpoint/every_steps=20 --set checkpoint/keep=5)
  # rebalance: a checkpoint every 4 steps (the rebalance interval) and 8 more steps, so that a
  # checkpoint follows the first move of the cut lines wherever the flow puts it before step 44
  [ "${targs[1]}" = rebalance ] && end=48 every=(--set checkpoint/every_steps=4 --set checkpoint/keep=20)
  run "$n" "$W/A" "${c[@]}" "${every[@]}" --max-steps $end; expect_ok $? "$W/A"
  run "$n" "$W/B" "${c[@]}" "${every[@]}" --max-steps 30; expect_ok $? "$W/B"
  [ -f "$(ck "$W/B" 30)" ] || fail "no checkpoint at the end of the interrupted run"
  run "$n" "$W/B" "${c[@]}" "${every[@]}" --max-steps $end --restart "$(ck "$W/B" 20)"
  expect_ok $? "$W/B"
  $cmp "$(ck "$W/A" $end)" "$(ck "$W/B" $end)" bitwise || fail "the state after restart differs"
  if [ "${targs[1]}" = rebalance ]; then
    # the cuts set at step 0 move again at step m > 0: a restart from the first checkpoint after
    # m takes the file's cut lines, not those the case gives at step 0
    moves=$(grep -c "cut lines" "$W/A.log")
    m=$(sed -n 's/.*step \([1-9][0-9]*\): cut lines.*/\1/p' "$W/A.log" | head -n 1)
    [ -n "$m" ] || fail "the cut lines never moved after step 0 ($moves moves in all)"
    r=$(((m / 4 + 1) * 4))
    [ "$r" -lt "$end" ] || fail "the cut lines first moved at step $m, too late for a checkpoint"
    echo "the cut lines first moved at step $m; restarting from the checkpoint of step $r"
    run "$n" "$W/C" "${c[@]}" "${every[@]}" --max-steps $end --restart "$(ck "$W/A" "$r")"
    expect_ok $? "$W/C"
    $cmp "$(ck "$W/A" $end)" "$(ck "$W/C" $end)" bitwise ||
      fail "the state after restart at step $r differs"
  fi
  for f in timeseries.csv solids.csv forces.csv picdem.xdmf cells.xdmf solids.xdmf obstacles.xdmf \
    particles.xdmf; do
    [ -e "$W/A/$f" ] || [ -e "$W/B/$f" ] || continue  # a grid the case does not have
    cmp "$W/A/$f" "$W/B/$f" || fail "$f differs after restart"
  done
  for f in "$W"/A/frames/*_particles.xdmf; do
    cmp "$f" "$W/B/frames/$(basename "$f")" || fail "frames/$(basename "$f") differs after restart"
  done
  echo "restart == continuous run, bitwise, on $n rank(s): state and output identical"
  ;;
ranks)
  # N -> M: a checkpoint written on N ranks continued on M ranks stays within the linear solver
  # tolerance of the uninterrupted N-rank run over 20 steps.
  n=${targs[0]} m=${targs[1]}
  every=(--set checkpoint/every_steps=20 --set checkpoint/keep=5)
  run "$n" "$W/A" "${disks[@]}" "${every[@]}" --max-steps 40; expect_ok $? "$W/A"
  run "$m" "$W/B" "${disks[@]}" "${every[@]}" --max-steps 40 --restart "$(ck "$W/A" 20)"
  expect_ok $? "$W/B"
  # positions/velocities within 1e-5 (m, m/s), pressure within 1e-5 of its largest value
  $cmp "$(ck "$W/A" 40)" "$(ck "$W/B" 40)" close 1e-5 1e-5 || fail "$n -> $m ranks: not close"
  ;;
ranks_straddling)
  # N -> M with solids across the rank boundaries, at the default solver tolerance: the
  # checkpoint of step 20 (written on N ranks) continued on M ranks and, from the same file, on N
  # ranks to step 40; positions (particles and solids, and the solids' angles) agree within 1e-7
  # m, velocities within 1e-5 m/s and pressure within 1e-5 of its largest value (the solver
  # tolerance's reach, as the other N -> M tests).
  # Checked in the checkpoints: solids straddle a boundary of the N-rank and of the M-rank cut
  # (of each that has more than 1 rank).
  n=${targs[0]} m=${targs[1]}
  straddle=(tests/restart/run/disks_straddling.yaml --set checkpoint/every_steps=20
            --set checkpoint/keep=5)
  run "$n" "$W/A" "${straddle[@]}" --max-steps 20; expect_ok $? "$W/A"
  run "$m" "$W/B" "${straddle[@]}" --max-steps 40 --restart "$(ck "$W/A" 20)"; expect_ok $? "$W/B"
  run "$n" "$W/C" "${straddle[@]}" --max-steps 40 --restart "$(ck "$W/A" 20)"; expect_ok $? "$W/C"
  for f in "$(ck "$W/A" 20)" "$(ck "$W/B" 40)"; do
    $python - "$f" << 'EOF' || fail "no solid straddles a rank boundary in $f"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    boxes = f["grid/boxes"][()].reshape(-1, 24)  # per rank: 3 staggers x (storage, owned) x 4
    h, nx = 0.002, 60  # the case's cell size and cells along x
    cuts = sorted({int(b[21]) for b in boxes if b[21] != nx})  # owned cells' upper x index
    radius = {0: 0.006, 1: 0.006, 2: 0.005, 3: 0.005}  # the case's disks, by id
    n = sum(1 for i, x in zip(f["dem/id"][()], f["dem/x"][()])
            if any(abs(x - c * h) < radius[int(i)] for c in cuts))
    print(f"{sys.argv[1]}: {len(boxes)} ranks, cuts at x = {[c * h for c in cuts]} m, "
          f"{n} solid(s) across them")
    sys.exit(0 if n > 0 or len(boxes) == 1 else 1)  # 1 rank: no boundary to straddle
EOF
  done
  $cmp "$(ck "$W/C" 40)" "$(ck "$W/B" 40)" close 1e-5 1e-7 1e-5 ||
    fail "$n -> $m ranks with straddling solids: not within 1e-7 of the $n-rank restart"
  ;;
layout)
  # The same 2 ranks in another layout (2 x 1 blocks -> 1 x 2): the checkpoint is read as on
  # another rank count, never slice by slice. A dam break without solids (the N -> M restarts with
  # solids across rank boundaries are ranks_straddling's).
  dam=(cases/dam_break/case.yaml --set grid/cell_size=0.004 --set output/png=false
       --set checkpoint/every_steps=20 --set checkpoint/keep=5)
  run 2 "$W/A" "${dam[@]}" --set grid/ranks_x=2 --set grid/ranks_z=1 --max-steps 40
  expect_ok $? "$W/A"
  run 2 "$W/B" "${dam[@]}" --set grid/ranks_x=1 --set grid/ranks_z=2 --max-steps 40 \
    --restart "$(ck "$W/A" 20)"
  expect_ok $? "$W/B"
  $cmp "$(ck "$W/A" 40)" "$(ck "$W/B" 40)" close 1e-5 1e-5 || fail "2 x 1 -> 1 x 2: not close"
  ;;
kill_during_write)
  # SIGKILL while the checkpoint of step 40 is being written (the writer pauses in the middle of
  # the data: the particles written, the grid and the solids not yet): the partial .tmp is smaller
  # than the complete file and refused as a checkpoint, step 20's checkpoint survives, the run
  # restarts from it and ends with the state of an uninterrupted run.
  read -r -a c <<< "$(case_args floating_disk)"
  every=(--set checkpoint/every_steps=20 --set checkpoint/keep=5)
  "$picdem" "${c[@]}" "${every[@]}" --max-steps 60 -o "$W/A" > "$W/A.log" 2>&1 ||
    fail "uninterrupted run failed"
  paused="checkpoint paused in the middle of the data"
  PICDEM_CHECKPOINT_PAUSE_AT_STEP=40 "$picdem" "${c[@]}" "${every[@]}" --max-steps 60 \
    -o "$W/B" > "$W/B.log" 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    grep -q "$paused" "$W/B.log" && break
    sleep 0.1
  done
  grep -q "$paused" "$W/B.log" || { kill -9 $pid; fail "no pause seen"; }
  kill -9 $pid
  wait $pid 2> /dev/null
  tmp="$(ck "$W/B" 40).tmp"
  [ -f "$tmp" ] || fail "no partial checkpoint_00000040.h5.tmp left by the kill"
  [ -f "$(ck "$W/B" 40)" ] && fail "a checkpoint of step 40 was committed before the kill"
  [ -f "$(ck "$W/B" 20)" ] || fail "the previous checkpoint (step 20) is gone"
  # the kill came before the grid's data: the .tmp lacks at least their bytes
  part=$(stat -c %s "$tmp") full=$(stat -c %s "$(ck "$W/A" 40)")
  grid=$($python -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); \
print(sum(f['grid'][n].id.get_storage_size() for n in f['grid']))" "$(ck "$W/A" 40)") ||
    fail "cannot read the grid's size"
  echo "killed during the write: the .tmp holds $part bytes, the complete file $full, its grid data $grid"
  [ $((part + grid)) -le "$full" ] || fail "the .tmp holds the grid's data: killed after the data"
  cp "$tmp" "$W/partial.h5"
  "$picdem" "${c[@]}" --max-steps 41 --restart "$W/partial.h5" -o "$W/P" > "$W/P.log" 2>&1
  code=$?
  [ $code -eq 2 ] || fail "the partial file was not refused (exit code $code): $(tail -3 "$W/P.log")"
  echo "the partial file is refused: $(grep -m1 "partial.h5" "$W/P.log")"
  "$picdem" "${c[@]}" "${every[@]}" --max-steps 60 --restart latest -o "$W/B" > "$W/B2.log" 2>&1 ||
    fail "restart after the kill failed: $(tail -3 "$W/B2.log")"
  grep -q "restarted from .*checkpoint_00000020.h5" "$W/B2.log" || fail "did not restart from step 20"
  $cmp "$(ck "$W/A" 60)" "$(ck "$W/B" 60)" bitwise || fail "state after the kill and restart differs"
  cmp "$W/A/timeseries.csv" "$W/B/timeseries.csv" || fail "timeseries.csv differs"
  ;;
sigterm | sigusr1)
  # A stop signal mid-run: the step finishes, a checkpoint is written, exit code 0; the run
  # continued from it ends bitwise equal to an uninterrupted run. SIGTERM goes to the process
  # (1 rank), SIGUSR1 through mpirun to 2 ranks (Open MPI forwards it).
  # (2 ranks: the disks case, whose solids never straddle a rank boundary)
  quiet=(--set output/progress_seconds=0 --set checkpoint/at_end=true)
  if [ "$test" = sigterm ]; then
    sig=TERM launch=()
    read -r -a c <<< "$(case_args floating_disk)"
  else
    sig=USR1 launch=("${mpi[@]}" -n 2)
    read -r -a c <<< "$(case_args disks)"
  fi
  "${launch[@]}" "$picdem" "${c[@]}" "${quiet[@]}" --max-steps 80 -o "$W/A" > "$W/A.log" 2>&1 ||
    fail "uninterrupted run failed"
  "${launch[@]}" "$picdem" "${c[@]}" "${quiet[@]}" --max-steps 80 -o "$W/B" > "$W/B.log" 2>&1 &
  pid=$!
  for _ in $(seq 1200); do
    grep -q "step 10 " "$W/B.log" && break
    sleep 0.05
  done
  kill -$sig $pid
  wait $pid
  code=$?
  [ $code -eq 0 ] || fail "exit code $code after SIG$sig (expected 0): $(tail -3 "$W/B.log")"
  grep -q "stop signal at step [0-9]*: checkpoint written" "$W/B.log" || fail "no checkpoint on SIG$sig"
  stop=$(sed -n 's/.*stop signal at step \([0-9]*\): checkpoint written.*/\1/p' "$W/B.log")
  [ "$stop" -lt 80 ] || fail "the signal arrived too late (step $stop)"
  "${launch[@]}" "$picdem" "${c[@]}" "${quiet[@]}" --max-steps 80 --restart latest -o "$W/B" \
    > "$W/B2.log" 2>&1 || fail "restart failed: $(tail -3 "$W/B2.log")"
  $cmp "$(ck "$W/A" 80)" "$(ck "$W/B" 80)" bitwise || fail "state differs after SIG$sig at $stop"
  cmp "$W/A/timeseries.csv" "$W/B/timeseries.csv" || fail "timeseries.csv differs"
  echo "SIG$sig at step $stop: continued run identical to the uninterrupted one"
  ;;
bad_files)
  # Each bad checkpoint stops the run with exit code 2 and its own message.
  read -r -a c <<< "$(case_args floating_disk)"
  "$picdem" "${c[@]}" --max-steps 5 -o "$W/A" > "$W/A.log" 2>&1 || fail "run failed"
  good=$(ck "$W/A" 5)
  [ -f "$good" ] || fail "no checkpoint at the end"
  check() {  # name, expected text, file, extra args...
    local name=$1 expect=$2 file=$3
    shift 3
    out=$(timeout 120 "$picdem" "${c[@]}" --max-steps 6 --restart "$file" "$@" -o "$W/$name" 2>&1)
    code=$?
    [ $code -eq 2 ] || fail "$name: exit code $code, expected 2: $(echo "$out" | tail -3)"
    grep -qF -- "$expect" <<< "$out" || fail "$name: message lacks '$expect': $out"
    echo "$name: $(grep -F -- "$expect" <<< "$out" | head -1)"
  }
  cp "$good" "$W/truncated.h5" && truncate -s $(($(stat -c %s "$good") / 2)) "$W/truncated.h5"
  check truncated "is not a readable HDF5 file (truncated or corrupted)" "$W/truncated.h5"
  cp "$good" "$W/corrupted.h5"
  $python - "$W/corrupted.h5" << 'EOF' || fail "cannot corrupt the file"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    offset = f["particles/u"].id.get_offset()
with open(sys.argv[1], "r+b") as f:
    f.seek(offset + 800)
    f.write(b"\x7f" * 16)
EOF
  check corrupted "fails its checksum (corrupted)" "$W/corrupted.h5"
  cp "$good" "$W/version.h5"
  $python -c "import h5py,sys; f=h5py.File(sys.argv[1],'r+'); f.attrs['format_version']=99; f.close()" \
    "$W/version.h5" || fail "cannot change the version"
  check other_version "has format version 99" "$W/version.h5"
  check other_case "belongs to another case; these keys differ" "$good" --set fluid/density=1100
  check other_case_key "fluid/density: 1000" "$good" --set fluid/density=1100
  check missing "does not exist" "$W/no_such_checkpoint.h5"
  check no_latest "no checkpoint (checkpoint_*.h5) in" latest --set checkpoint/directory="$W/empty"
  # allowed to differ: time/end, grid/ranks_x, grid/ranks_z, output/*, checkpoint/*, solver/*
  "$picdem" "${c[@]}" --max-steps 6 --restart "$good" --set time/end=2 --set solver/tolerance=1e-9 \
    --set grid/ranks_x=1 --set grid/ranks_z=1 \
    -o "$W/allowed" > "$W/allowed.log" 2>&1 || fail "restart with allowed changes failed"
  ;;
blow_up)
  # A dam break allowed 5 times the CFL limit (dt_max 0.01 s; it blows up near step 4): exit
  # code 3 and a message naming the step; the checkpoints left are of good steps, the newest loads.
  bad=(cases/dam_break/case.yaml --set grid/cell_size=0.004 --set output/png=false
       --set time/cfl=5 --set time/dt_max=0.01 --set checkpoint/every_steps=1
       --set checkpoint/keep=3)
  run 1 "$W/A" "${bad[@]}" --max-steps 100
  code=$?
  [ $code -eq 3 ] || fail "exit code $code, expected 3: $(tail -3 "$W/A.log")"
  grep -q "the run stopped: step [0-9]* at t = .*CFL condition is far exceeded" "$W/A.log" ||
    fail "no CFL diagnostic: $(tail -3 "$W/A.log")"
  step=$(sed -n 's/.*the run stopped: step \([0-9]*\) at t.*/\1/p' "$W/A.log")
  last=$(ls "$W/A/checkpoints" | sed -n 's/checkpoint_0*\([0-9]*\)\.h5$/\1/p' | sort -n | tail -1)
  [ "$last" = $((step - 1)) ] || fail "newest checkpoint is of step $last, blown step $step"
  # the blown-up step's state is the last frame and the last row of timeseries.csv (to see where)
  [ -f "$W/A/frames/$(printf 'frame_%06d.h5' "$step")" ] || fail "no frame of the blown-up step $step"
  row=$(tail -1 "$W/A/timeseries.csv" | cut -d, -f3)
  [ "$row" = "$step" ] || fail "last timeseries.csv row is of step $row, blown step $step"
  run 1 "$W/B" "${bad[@]}" --max-steps $((step - 1)) --restart latest \
    --set checkpoint/directory="$W/A/checkpoints"
  expect_ok $? "$W/B"
  echo "blown up at step $step, last good checkpoint of step $last loads"
  # Two disks whose real boundaries overlap: refused before the first step (input checks, exit
  # code 2), naming both solids and the overlap.
  cat > "$W/overlap.yaml" << 'EOF'
grid: {length: 0.1, height: 0.1, cell_size: 0.002}
solids:
  a: {type: disk, radius: 0.01, center: [0.05, 0.05], density: 1000.0}
  b: {type: disk, radius: 0.01, center: [0.06, 0.05], density: 1000.0}
time: {end: 0.1}
output: {png: false}
EOF
  run 1 "$W/C" "$W/overlap.yaml" --max-steps 5
  code=$?
  [ $code -eq 2 ] || fail "overlap: exit code $code, expected 2: $(tail -3 "$W/C.log")"
  grep -q "solids/a (id 0) and solids/b (id 1) overlap by 0.01 m" "$W/C.log" ||
    fail "no overlap diagnostic: $(tail -3 "$W/C.log")"
  [ -d "$W/C/checkpoints" ] && [ -n "$(ls "$W/C/checkpoints")" ] && fail "overlap: a step was run"
  ;;
extend)
  # A run to t = 0.05 s continued with --set time/end=0.1 takes the steps of one run made to
  # 0.1 s: the end checkpoints are bitwise equal and so is timeseries.csv. (Before, the step that
  # landed exactly on the first end time was shortened and the two runs parted there.)
  read -r -a c <<< "$(case_args floating_disk)"
  quiet=(--set output/progress_seconds=0 --set checkpoint/at_end=true --set checkpoint/keep=5)
  "$picdem" "${c[@]}" "${quiet[@]}" --set time/end=0.1 -o "$W/A" > "$W/A.log" 2>&1 ||
    fail "run to 0.1 s failed"
  "$picdem" "${c[@]}" "${quiet[@]}" --set time/end=0.05 -o "$W/B" > "$W/B.log" 2>&1 ||
    fail "run to 0.05 s failed"
  first=$(ls "$W/B/checkpoints" | tail -1)
  "$picdem" "${c[@]}" "${quiet[@]}" --set time/end=0.1 --restart latest -o "$W/B" \
    > "$W/B2.log" 2>&1 || fail "continued run failed: $(tail -3 "$W/B2.log")"
  grep -q "restarted from .*$first" "$W/B2.log" || fail "did not continue from $first"
  end_a=$(ls "$W/A/checkpoints" | tail -1) end_b=$(ls "$W/B/checkpoints" | tail -1)
  [ "$end_a" = "$end_b" ] || fail "runs ended at different steps: $end_a vs $end_b"
  $cmp "$W/A/checkpoints/$end_a" "$W/B/checkpoints/$end_b" bitwise ||
    fail "continued run differs from the run made to the later end"
  cmp "$W/A/timeseries.csv" "$W/B/timeseries.csv" || fail "timeseries.csv differs"
  echo "run to 0.05 s continued to 0.1 s: $end_b bitwise equal to the run made to 0.1 s"
  ;;
schedule)
  # every_seconds (tiny: after every step) with keep = 3 leaves exactly the newest three; a fresh
  # run in the same folder removes them first; every_steps = 4 with at_end writes 4, 8 and 10.
  read -r -a c <<< "$(case_args floating_disk)"
  "$picdem" "${c[@]}" --set checkpoint/every_seconds=1e-9 --set checkpoint/keep=3 --max-steps 6 \
    -o "$W/A" > "$W/A.log" 2>&1 || fail "run failed"
  got=$(ls "$W/A/checkpoints" | tr '\n' ' ')
  [ "$got" = "checkpoint_00000004.h5 checkpoint_00000005.h5 checkpoint_00000006.h5 " ] ||
    fail "every_seconds/keep left: $got"
  "$picdem" "${c[@]}" --set checkpoint/every_steps=4 --set checkpoint/keep=5 --max-steps 10 \
    -o "$W/A" > "$W/A.log" 2>&1 || fail "second run failed"
  got=$(ls "$W/A/checkpoints" | tr '\n' ' ')
  [ "$got" = "checkpoint_00000004.h5 checkpoint_00000008.h5 checkpoint_00000010.h5 " ] ||
    fail "every_steps/at_end left: $got"
  ;;
frames)
  # output/interval may change on restart (doc/restart.md): a run to 0.05 s with one frame a
  # second, continued to 0.1 s with a frame every 0.01 s, writes the continued run's frames at
  # 0.06, 0.07, 0.08, 0.09 and 0.1 s. (Before, the checkpoint's next frame time, 1 s, held until
  # it was reached: no frame but the end one.)
  read -r -a c <<< "$(case_args floating_disk)"
  quiet=(--set output/progress_seconds=0 --set checkpoint/at_end=true --set output/png=false)
  "$picdem" "${c[@]}" "${quiet[@]}" --set time/end=0.05 --set output/interval=1 -o "$W/A" \
    > "$W/A.log" 2>&1 || fail "run to 0.05 s failed"
  before=$(ls "$W/A/frames" | grep -c '\.h5$')
  "$picdem" "${c[@]}" "${quiet[@]}" --set time/end=0.1 --set output/interval=0.01 \
    --restart latest -o "$W/A" > "$W/A2.log" 2>&1 || fail "continued run failed: $(tail -3 "$W/A2.log")"
  times=$("$python" -c '
import re, sys
t = [float(x) for x in re.findall(r"<Time Value=\"([^\"]+)\"", open(sys.argv[1]).read())]
print(" ".join("%.2f" % x for x in t if x > 0.0501))' "$W/A/cells.xdmf")
  [ "$times" = "0.06 0.07 0.08 0.09 0.10" ] ||
    fail "frames after the restart at: '$times' (expected 0.06 0.07 0.08 0.09 0.10; $before before)"
  echo "frames after the restart with output/interval 1 -> 0.01: $times"
  ;;
*)
  fail "unknown test $test"
  ;;
esac
echo "PASS $test"
