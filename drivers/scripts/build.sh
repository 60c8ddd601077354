#!/usr/bin/env bash
# Configures and builds picdem in ./build (Release, ccache when present, 2 jobs).
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${PICDEM_BUILD_DIR:-$top/build}
# ccache: paths relative to the source tree, so that clones share the cache.
export CCACHE_BASEDIR="$top"
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"${PICDEM_JOBS:-2}"
