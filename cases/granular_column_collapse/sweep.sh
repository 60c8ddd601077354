#!/usr/bin/env bash
# The five aspect ratios of the column collapse, three runs at a time, then analyse.py.
# Each run ends when its deposit has come to rest (checked by analyse.py over the last 0.1 s).
# usage: sweep.sh PICDEM OUT_DIR [extra picdem args]
set -euo pipefail
picdem=$1; out=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
declare -A width=([0.5]=0.2113 [1]=0.1494 [2]=0.1056 [4]=0.0747 [8]=0.0528)
declare -A end=([0.5]=0.8 [1]=0.9 [2]=1.1 [4]=1.3 [8]=1.5)
mkdir -p "$out"
for a in 8 4 2 1 0.5; do
  "$picdem" "$here/case.yaml" --output "$out/a$a" --set "time/end=${end[$a]}" \
    --set "solids/grains/region=[0, 0.006, ${width[$a]}, 0.8]" "$@" > "$out/a$a.log" 2>&1 &
  while [ "$(jobs -rp | wc -l)" -ge 3 ]; do sleep 2; done
done
wait
/usr/bin/python3 "$here/analyse.py" "$out"
