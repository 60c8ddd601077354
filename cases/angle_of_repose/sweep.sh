#!/usr/bin/env bash
# dem/mu = 0.1, 0.2, 0.3, 0.4, each without (mu_r = 0) and with rolling resistance (mu_r = 0.1),
# JOBS runs at a time (default 1), at nice 5, then analyse.py.
# usage: sweep.sh PICDEM OUT_DIR [extra picdem args]       (env JOBS, MU_LIST, MUR_LIST)
set -euo pipefail
picdem=$1; out=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
for mur in ${MUR_LIST:-0 0.1}; do
  for mu in ${MU_LIST:-0.1 0.2 0.3 0.4}; do
    run="mu${mu}_mur${mur}"
    nice -n 5 "$picdem" "$here/case.yaml" --output "$out/$run" --set "dem/mu=$mu" \
      --set "dem/rolling_resistance=$mur" --set checkpoint/at_end=false "$@" > "$out/$run.log" 2>&1 &
    while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-1}" ]; do sleep 2; done
  done
done
wait
/usr/bin/python3 "$here/analyse.py" "$out"
