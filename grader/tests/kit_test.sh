#!/usr/bin/env bash
# The student kit as a student meets it.   kit_test.sh GRADER SOURCE_DIR WORK_DIR
#
# 1. export-kit writes a kit that holds nothing instructor-only and has the student's README;
# 2. in the kit, the README's runnable commands work as written (the build: tools/setup
#    --preset student; the submission archive);
# 3. the kit's whole ctest fails only stage tests on the stubs, and some of every stage's;
# 4. with finished pieces in place of the stubs (the reference's .cc files, through
#    VL_SOURCE_DIR_NN, as a student who has done every stage), every test passes and
#    every command the README and the handouts mark runnable works.
set -euo pipefail
grader=$1 source=$2 work=$3
kit=$work/kit
fail() { echo "kit_test: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
"$grader" export-kit "$kit" >"$work/export.log"
test -f "$work/kit.tar.gz" || fail "export-kit wrote no $work/kit.tar.gz"
for forbidden in reference grader/hidden grader/tests grader/src .ci tools/update-reference-images tools/test; do
  [ ! -e "$kit/$forbidden" ] || fail "$forbidden is in the kit"
done
cmp -s "$source/kit/README.md" "$kit/README.md" || fail "the kit's README.md is not kit/README.md"
cmp -s "$source/LICENSE" "$kit/LICENSE" || fail "the kit's LICENSE is not the project's"
grep -rn "tools/update-reference-images\|grader/run " "$kit/assignments" "$kit/framework" "$kit/pieces" \
  "$kit/README.md" >"$work/instructor-only.txt" && fail "the kit tells students to run instructor-only commands:
$(cat "$work/instructor-only.txt")"

# The README's commands, as written, in the kit's top folder (the build among them).
snippets=$source/tools/run-snippets
"$snippets" --dir "$kit" "$kit/README.md" >"$work/readme.log" 2>&1 ||
  fail "a command of the kit's README failed:
$(tail -n 40 "$work/readme.log")"
grep -q "^VL_PIECES:STRING=student$" "$kit/build/student/CMakeCache.txt" || fail "the kit's build is not of the stubs"

# Stubs: every failure is a stage's test, and every stage has failures.
stages=$(cd "$kit/assignments" && ls -d [0-9][0-9]-*/ | tr -d /)
[ -n "$stages" ] || fail "the kit has no stages"
(cd "$kit" && ctest --preset student --timeout 120 >"$work/ctest-stubs.log" 2>&1) &&
  fail "every test passes on the stubs; the stages' tests should fail"
failed=$kit/build/student/Testing/Temporary/LastTestsFailed.log
[ -s "$failed" ] || fail "ctest failed but listed no failed test (see $work/ctest-stubs.log)"
stage_pattern=$(echo "$stages" | paste -sd'|')
if grep -Ev "^[0-9]+:($stage_pattern): ?" "$failed" >"$work/not-stage.txt"; then
  fail "tests that are not a stage's fail on the stubs:
$(cat "$work/not-stage.txt")"
fi
for stage in $stages; do
  grep -q "^[0-9]*:$stage: \?" "$failed" || fail "no test of $stage fails on the stubs"
done
total=$(cd "$kit" && ctest --preset student -N | sed -n 's/^Total Tests: //p')

# Finished pieces: every stage's .cc files from the reference, as a student who is done.
defs=()
for stage in $stages; do defs+=("-DVL_SOURCE_DIR_${stage%%-*}=$source/reference/$stage"); done
(cd "$kit" && cmake --preset student "${defs[@]}" >"$work/configure-solved.log" &&
  cmake --build --preset student >"$work/build-solved.log") || fail "the kit does not build with finished pieces:
$(tail -n 30 "$work/build-solved.log" 2>/dev/null || tail -n 30 "$work/configure-solved.log")"
(cd "$kit" && ctest --preset student --timeout 120 >"$work/ctest-solved.log" 2>&1) ||
  fail "with finished pieces some tests fail:
$(grep -E '^\s+[0-9]+ - ' "$work/ctest-solved.log" | head -n 20)"
handouts=()
for stage in $stages; do handouts+=("$kit/assignments/$stage/README.md"); done
"$snippets" --dir "$kit" --tag solved "$kit/README.md" "${handouts[@]}" >"$work/solved-snippets.log" 2>&1 ||
  fail "with finished pieces a command of the README or a handout failed:
$(tail -n 40 "$work/solved-snippets.log")"

echo "kit_test: the kit is clean; its README's commands work; on the stubs only stage tests fail" \
     "($(wc -l <"$failed") of $total, in every stage); with finished pieces all $total pass" \
     "and $(grep -c ': ok$' "$work/solved-snippets.log") documented commands work"
