#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the fall pipe (continuous) on 2 ranks at
# a reduced resolution (h = 1.5 mm, the first 1.0 s of dumping; about two minutes on 2 cores after the build), then plots
# the water levels and the cylinders leaving the pipe, and joins the pictures into a movie
# (pictures/movie.mp4 with ffmpeg, movie.gif without). Prints where everything is.
# Extra arguments go to picdem (e.g. --set time/end=2.0, or --restart latest to continue).
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
bash "$top/drivers/scripts/install_deps.sh"
bash "$top/drivers/scripts/build.sh"
case_file=${PICDEM_MAIN_CASE:-$top/cases/fall_pipe_continuous/case.yaml}
out=${PICDEM_MAIN_OUT:-$top/output/main_job}
mpiexec=(mpirun -n 2)
[ "$(id -u)" -eq 0 ] && mpiexec+=(--allow-run-as-root)
"${mpiexec[@]}" "${PICDEM_BUILD_DIR:-$top/build}/drivers/picdem" "$case_file" --output "$out" \
  --set grid/cell_size=0.0015 --set time/end=1.0 --set output/interval=0.05 \
  --set output/png_speed_max=1.0 --set output/movie=true "$@"
/usr/bin/python3 "$top/drivers/plot/fall_pipe.py" "$out" --labels "continuous pipe" \
  --out "$out/pictures/levels_and_cylinders.png"
movie=$(ls "$out"/pictures/movie.mp4 "$out"/pictures/movie.gif 2>/dev/null | head -n 1 || true)
echo "main job done: pictures in $out/pictures (frame_NNNNNN.png with NNNNNN the step, as frames/,"
echo "levels_and_cylinders.png), movie: ${movie:-none (see the end of $out/picdem.log)},"
echo "ParaView: $out/picdem.xdmf, checkpoints: $out/checkpoints (continue with: bash $0 --restart latest --set time/end=1.6)"
