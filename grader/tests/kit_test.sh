#!/usr/bin/env bash
# Exports the student kit, builds it with -DVL_PIECES=student and runs its public tests,
# which must exist and fail on the stubs.   kit_test.sh GRADER WORK_DIR
set -euo pipefail
grader=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
"$grader" export-kit "$work/kit"
test -f "$work/kit.tar.gz"
for forbidden in reference grader/hidden grader/tests grader/src; do
  if [ -e "$work/kit/$forbidden" ]; then echo "kit_test: $forbidden is in the kit" >&2; exit 1; fi
done
cmake -S "$work/kit" -B "$work/kit/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVL_PIECES=student \
  -DVL_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >"$work/configure.log"
grep -q "pieces from $work/kit/assignments" "$work/configure.log" || { echo "kit_test: not built from the stubs" >&2; exit 1; }
targets=$(cd "$work/kit/build" && ninja -t targets all | sed -n 's/^\(stage_[0-9]*_public_test\): .*/\1/p' | sort -u)
[ -n "$targets" ] || { echo "kit_test: the kit has no public tests" >&2; exit 1; }
cmake --build "$work/kit/build" --target $targets -j 2 >"$work/build.log"
if ctest --test-dir "$work/kit/build" -L '^0[0-9]-' --timeout 60 >"$work/ctest.log" 2>&1; then
  echo "kit_test: the public tests pass on the stubs; they should fail" >&2; exit 1
fi
grep -q "tests failed out of" "$work/ctest.log"
echo "kit_test: the kit is clean, builds from the stubs, and $(grep -o '[0-9]* tests failed out of [0-9]*' "$work/ctest.log")"
