#!/usr/bin/env bash
# cmake --install of the build tree into a fresh prefix, then the project in consumer/ (outside
# picdem's tree) configured against that prefix only, built and run.
# usage: install_and_use.sh CMAKE BUILD_DIR SOURCE_DIR WORK_DIR
set -u
cmake=$1 build=$2 src=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || exit 1
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 ||
  { tail -20 "$work/install.log"; fail "cmake --install"; }
for f in lib/libpicdem_core.a lib/libpicdem_geometry.a lib/libpicdem_coupling.a bin/picdem \
         include/picdem/geometry/shape.hpp include/picdem/io/frame_writer.hpp \
         lib/cmake/picdem/picdemConfig.cmake lib/cmake/picdem/picdemConfigVersion.cmake; do
  [ -e "$work/prefix/$f" ] || fail "$f not installed"
done
[ -e "$work/prefix/include/picdem/io/h5.hpp" ] && fail "a private header (io/src/h5.hpp) was installed"
# The package points at the prefix, never back into the source or build tree.
grep -l -e "$src" -e "$build" "$work"/prefix/lib/cmake/picdem/*.cmake &&
  fail "the package config names the source or build tree"
"$cmake" -S "$src/tests/unit/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" 2>&1 ||
  { tail -20 "$work/configure.log"; fail "configuring the consumer"; }
"$cmake" --build "$work/consumer" > "$work/build.log" 2>&1 ||
  { tail -20 "$work/build.log"; fail "building the consumer"; }
"$work/consumer/square_shape" || fail "the consumer's checks"
echo "installed package found, built against and run from $work/consumer"
