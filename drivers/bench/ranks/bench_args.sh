# Sourced by the rank benchmarks in this folder: reads their common arguments
# [PICDEM] [ROUNDS] [END] [CASE] [-- extra --set args] and sets picdem, rounds, end, case_file,
# mpi (the mpirun prefix, with --allow-run-as-root as root), work (a fresh directory under
# PICDEM_BENCH_DIR or /tmp, named after $bench_name) and common (the --set arguments every run
# takes: the end time, no pictures, no ParaView files, no final checkpoint, then the extra ones).
# The caller sets default_end before sourcing.
picdem=${1:-build/drivers/picdem}
rounds=${2:-3}
end=${3:-$default_end}
case_file=${4:-cases/dam_break_cylinders_6_layers/case.yaml}
shift $(($# < 4 ? $# : 4))
[ "${1:-}" = "--" ] && shift
extra=("$@")
mpi=(mpirun --oversubscribe)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
work=$(mktemp -d "${PICDEM_BENCH_DIR:-/tmp}/picdem_$bench_name.XXXXXX")
common=(--set "time/end=$end" --set output/paraview=false --set output/png=false
        --set checkpoint/at_end=false "${extra[@]}")
