#!/usr/bin/env bash
# The five aspect ratios of the column collapse (1,000 disks each), JOBS runs at a time (default 1),
# niced, then analyse.py. Each run ends when its deposit has come to rest (checked by analyse.py
# over the last 0.1 s). No checkpoint is written (case.yaml says why), so a run that has not come
# to rest must be rerun with a later time/end.
# usage: sweep.sh PICDEM OUT_DIR [extra picdem args]     (env JOBS, A_LIST="8 4 2 1 0.5")
set -euo pipefail
picdem=$1; out=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
declare -A width=([0.5]=0.2746 [1]=0.1942 [2]=0.1373 [4]=0.0971 [8]=0.0687)
declare -A end=([0.5]=1.0 [1]=1.1 [2]=1.3 [4]=1.5 [8]=1.8)
mkdir -p "$out"
for a in ${A_LIST:-8 4 2 1 0.5}; do
  nice -n 5 "$picdem" "$here/case.yaml" --output "$out/a$a" --set "time/end=${end[$a]}" \
    --set "solids/grains/region=[0, 0.006, ${width[$a]}, 0.8]" "$@" > "$out/a$a.log" 2>&1 &
  while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-1}" ]; do sleep 2; done
done
wait
/usr/bin/python3 "$here/analyse.py" "$out"
