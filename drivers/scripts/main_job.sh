#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on 2 ranks; prints where the pictures and
# ParaView files are.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
bash "$top/drivers/scripts/install_deps.sh"
bash "$top/drivers/scripts/build.sh"
case_file=${PICDEM_MAIN_CASE:-$top/cases/dam_break/case.yaml}
out=${PICDEM_MAIN_OUT:-$top/output/main_job}
mpiexec=(mpirun -n 2)
[ "$(id -u)" -eq 0 ] && mpiexec+=(--allow-run-as-root)
"${mpiexec[@]}" "${PICDEM_BUILD_DIR:-$top/build}/drivers/picdem" "$case_file" --output "$out" "$@"
