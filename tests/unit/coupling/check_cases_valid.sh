#!/usr/bin/env bash
# Every shipped case validates, and doc/parameters.md is exactly what the code declares.
# usage: check_cases_valid.sh PICDEM SOURCE_DIR
set -u
picdem=$1 src=$2
passed=0 failed=0
for f in "$src"/cases/*/case*.yaml "$src"/tests/unit/coupling/good_case.yaml; do
  if out=$("$picdem" --check "$f" 2>&1); then passed=$((passed + 1)); else
    echo "FAIL $f: $out"; failed=$((failed + 1)); fi
done
# A case directory stands for its case.yaml, and the run says which file it read.
if out=$("$picdem" --check "$src/cases/dam_break" 2>&1) && grep -qF "cases/dam_break/case.yaml: valid" <<< "$out"; then
  passed=$((passed + 1))
else
  echo "FAIL picdem --check cases/dam_break (a directory): $out"; failed=$((failed + 1))
fi
if diff -u "$src/doc/parameters.md" <("$picdem" --help-parameters) > /tmp/picdem_param_diff.$$ 2>&1; then
  passed=$((passed + 1))
else
  echo "FAIL doc/parameters.md differs from 'picdem --help-parameters' (regenerate it):"
  head -20 /tmp/picdem_param_diff.$$; failed=$((failed + 1))
fi
rm -f /tmp/picdem_param_diff.$$
# --help prints picdem's usage first (not the linear-algebra library's options) and exits 0
if out=$("$picdem" --help 2>&1) && [ "$(printf '%s\n' "$out" | head -1 | cut -c1-13)" = "usage: picdem" ]; then
  passed=$((passed + 1))
else
  echo "FAIL picdem --help: $(printf '%s\n' "$out" | head -3)"; failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
