#!/usr/bin/env bash
# The five aspect ratios of the column collapse (1,000 disks each), JOBS runs at a time (default 1),
# niced, then analyse.py. Each run ends when its deposit has come to rest (checked by analyse.py
# over the last 0.1 s). No checkpoint is written (case.yaml says why), so a run that has not come
# to rest must be rerun with a later time/end.
# COUNT (default 1000) disks per column: the widths scale with sqrt(COUNT / 1000) (the settled
# column holds about 26,500 disks per m^2), END_a (e.g. END_4=1.4) overrides a run's time/end.
# LENGTH and HEIGHT (default 1.5 and 0.8 m, case.yaml's) set a larger tank for columns of more
# disks: the case file is then written to OUT_DIR/case.yaml by make_teeth.py (teeth over the whole
# length) and the pour region reaches up to HEIGHT.
# usage: sweep.sh PICDEM OUT_DIR [extra picdem args]
#        (env JOBS, A_LIST="8 4 2 1 0.5", COUNT, END_0.5 .. END_8 as END_0_5 .. END_8, LENGTH, HEIGHT)
set -euo pipefail
picdem=$1; out=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
declare -A width=([0.5]=0.2746 [1]=0.1942 [2]=0.1373 [4]=0.0971 [8]=0.0687)
declare -A end=([0.5]=1.0 [1]=1.1 [2]=1.3 [4]=1.5 [8]=1.8)
mkdir -p "$out"
count=${COUNT:-1000}
case_file=$here/case.yaml
top=0.8
if [ -n "${LENGTH:-}${HEIGHT:-}" ]; then
  case_file=$out/case.yaml
  top=${HEIGHT:-0.8}
  /usr/bin/python3 "$here/make_teeth.py" --case "$here/case.yaml" --length "${LENGTH:-1.5}" \
    --height "$top" > "$case_file"
fi
for a in ${A_LIST:-8 4 2 1 0.5}; do
  w=$(awk -v w="${width[$a]}" -v n="$count" 'BEGIN { printf "%.4f", w * sqrt(n / 1000) }')
  e_var="END_${a/./_}"
  t_end=${!e_var:-${end[$a]}}
  nice -n 5 "$picdem" "$case_file" --output "$out/a$a" --set "time/end=$t_end" \
    --set "solids/grains/count=$count" --set "solids/grains/region=[0, 0.006, $w, $top]" "$@" \
    > "$out/a$a.log" 2>&1 &
  while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-1}" ]; do sleep 2; done
done
wait
/usr/bin/python3 "$here/analyse.py" "$out"
