#!/usr/bin/env bash
# One case of the adversarial suite (grader/tests/adversarial/README.md), as ctest runs it:
#
#   check_attack.sh GRADER CASE_DIR OUT_DIR [--no-policy]
#
# Grades the attack with `grader calibrate` (which checks expected.toml: the score's range,
# the verdict, the results.json format) within a time bound, then checks that nothing
# outside the grade's own output changed: the checkout, the build tree and /tmp are listed
# (path, size, mode, owner, mtime) before and after. ctest runs these tests one at a time
# (RUN_SERIAL), so nothing else changes those folders meanwhile.
set -uo pipefail
grader=$1 case_dir=$2 out=$3
shift 3
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "$(dirname "$grader")/.." && pwd)

manifest() {
  {
    find "$src" -path "$src/build" -prune -o -printf '%p %s %m %U %T@\n'
    find "$build" \( -path "$build/grader/calibration" -o -path "$build/grader/calibration-sources" \
      -o -path "$build/grader/adversarial" -o -path "$build/Testing" -o -path "$build/grader/kit-test" \) -prune \
      -o -printf '%p %s %m %U %T@\n'
    find /tmp -xdev -maxdepth 4 -printf '%p %s %m %U\n' 2>/dev/null
  } | sort
}

mkdir -p "$(dirname "$out")"
before=$(mktemp -d -p "$(dirname "$out")")
trap 'rm -rf "$before"' EXIT
manifest >"$before/list"
rm -rf "$out"
start=$(date +%s)
timeout --kill-after=10 900 "$grader" calibrate "$case_dir" --out "$out" "$@"
status=$?
elapsed=$(( $(date +%s) - start ))
manifest >"$before/after"
if ! diff -q "$before/list" "$before/after" >/dev/null; then
  echo "ATTACK: something outside the grade's output changed:"
  diff "$before/list" "$before/after" | head -40
  status=1
fi
if [ $status -eq 124 ] || [ $status -eq 137 ]; then
  echo "ATTACK: the grader did not finish within 900 s"
fi
echo "attack graded in ${elapsed} s"
exit $status
