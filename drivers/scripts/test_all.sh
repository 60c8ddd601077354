#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite through ctest.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
bash "$top/drivers/scripts/install_deps.sh" --tests
bash "$top/drivers/scripts/build.sh"
cd "${PICDEM_BUILD_DIR:-$top/build}"
ctest --output-on-failure --timeout 900 -j1 "$@"
