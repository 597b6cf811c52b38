#!/usr/bin/env bash
# The Gradescope bundle, made and used as Gradescope would (ctest label `grader`):
#   grader/tests/gradescope_test.sh GRADER SOURCE_DIR
# - `GRADER gradescope 02 OUT.zip` writes a zip with setup.sh and run_autograder at its top,
#   no build/ and no .git, the same bytes twice;
# - unpacked into $tmp/autograder/source, its setup.sh builds the grader there (not in
#   SOURCE_DIR/build);
# - run_autograder, with the VL_AUTOGRADER_* paths pointing into $tmp/autograder, grades the
#   reference (full marks), the stubs (0, in the weaker sandbox: VL_GRADER_BWRAP names no
#   bubblewrap) and a planted bug (its expected.toml's score range), and each results.json
#   names its sandbox in "output";
# - a grader that fails (a stand-in that exits 1; the real one refusing to grade without
#   bubblewrap under VL_AUTOGRADER_SANDBOX=bubblewrap) gives a results.json that says the
#   autograder failed, scores nothing, and run_autograder exits non-zero.
# The build reuses ccache across runs of this test (CCACHE_BASEDIR: the tree's path
# changes every run); without a cache it is a first build of the preset grader's target.
set -uo pipefail
grader=$1 src=$2
stage=02-sphere bug=inward-normal
fail=0
say() { echo "$*"; }
bad() { echo "FAILED: $*"; fail=1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
start=$SECONDS

# The bundle.
if ! "$grader" gradescope 02 "$tmp/bundle.zip" >"$tmp/make.log" 2>&1; then
  bad "gradescope 02 failed:"; cat "$tmp/make.log"; exit 1
fi
names=$(unzip -Z1 "$tmp/bundle.zip")
for top in setup.sh run_autograder autograder.conf CMakeLists.txt CMakePresets.json tools/setup \
           framework/CMakeLists.txt reference/$stage/sphere.cc grader/hidden/$stage/rubric.toml; do
  grep -qx "$top" <<<"$names" || bad "the bundle has no $top"
done
if grep -qE '^(build|\.git)(/|$)' <<<"$names"; then bad "the bundle holds build/ or .git: $(grep -E '^(build|\.git)' <<<"$names" | head -3)"; fi
unzip -Zl "$tmp/bundle.zip" run_autograder | grep -q '^-rwx' || bad "run_autograder is not executable in the zip"
grep -qx 'assignment=02-sphere' <(unzip -p "$tmp/bundle.zip" autograder.conf) || bad "autograder.conf does not name 02-sphere"
"$grader" gradescope 02 "$tmp/again.zip" >/dev/null 2>&1 && cmp -s "$tmp/bundle.zip" "$tmp/again.zip" ||
  bad "making the bundle twice gave different bytes"
if "$grader" gradescope 02 "$tmp/bundle.tar" >"$tmp/bad.log" 2>&1 || ! grep -q "must end in .zip" "$tmp/bad.log"; then
  bad "a bundle name without .zip: $(cat "$tmp/bad.log")"
fi
say "ok: the bundle has $(wc -l <<<"$names") files, setup.sh and run_autograder at its top, the same bytes twice"

# setup.sh, for real, in the simulated /autograder.
ag=$tmp/autograder
mkdir -p "$ag/source" "$ag/results"
unzip -q "$tmp/bundle.zip" -d "$ag/source"
cp "$ag/source/run_autograder" "$ag/run_autograder"  # as Gradescope does
own_build_before=$(ls "$src/build" 2>/dev/null)
build_start=$SECONDS
if ! CCACHE_BASEDIR="$ag/source" CCACHE_NOHASHDIR=1 bash "$ag/source/setup.sh" >"$tmp/setup.log" 2>&1 </dev/null; then
  bad "setup.sh failed; the end of its log:"; tail -n 40 "$tmp/setup.log"; exit 1
fi
say "ok: setup.sh built the bundle's grader in $((SECONDS - build_start)) s"
[ -x "$ag/source/build/grader/grader/grader" ] || bad "setup.sh built no $ag/source/build/grader/grader/grader"
grep -q "source_dir = \"$ag/source\"" "$ag/source/build/grader/grader/grader.toml" ||
  bad "the bundle's grader does not grade from the bundle's source"
[ "$(ls "$src/build" 2>/dev/null)" = "$own_build_before" ] || bad "setup.sh changed $src/build"
[ ! -e "$ag/source/build/grader/grader/vl_grader_trusted_01" ] || bad "setup.sh built another stage's tests"

# run_autograder on one submission: grade NAME DIR [ENV...]; leaves $tmp/NAME.json and $tmp/NAME.log.
grade() {
  local name=$1 from=$2
  shift 2
  rm -rf "$ag/submission" "$ag/results"/*
  mkdir -p "$ag/submission"
  cp -R "$from"/. "$ag/submission/"
  local t=$SECONDS
  env VL_AUTOGRADER_ROOT="$ag" VL_AUTOGRADER_OUT="$tmp/out-$name" "$@" "$ag/run_autograder" >"$tmp/$name.log" 2>&1
  local status=$?
  cp "$ag/results/results.json" "$tmp/$name.json" 2>/dev/null
  say "   ($name: run_autograder exited $status in $((SECONDS - t)) s)"
  return $status
}
# check NAME SANDBOX_WORD: results.json parses, has the documented fields, names its sandbox.
check() {
  local name=$1 word=$2
  if ! jq -e '(.score|type)=="number" and (.output|type)=="string" and (.tests|type)=="array"' "$tmp/$name.json" >/dev/null 2>&1; then
    bad "$name: no valid results.json; run_autograder said:"; tail -n 20 "$tmp/$name.log"; return 1
  fi
  if ! jq -r .output "$tmp/$name.json" | grep -q "^Sandbox: $word"; then
    bad "$name: output does not say 'Sandbox: $word': $(jq .output "$tmp/$name.json")"; return 1
  fi
}
score() { jq -r "$1" "$tmp/$2.json"; }

grade reference "$src/reference/$stage" || bad "run_autograder failed on the reference: $(tail -n 5 "$tmp/reference.log")"
if check reference bubblewrap; then
  got=$(score .score reference) max=$(score '[.tests[].max_score] | add | . * 10000 | round / 10000' reference)
  # The items' maxima are rounded to 1e-4 each: their sum is the total to within that.
  jq -e '(.score - ([.tests[].max_score] | add)) as $d | $d < 0.001 and $d > -0.001 and
         .score == .extra_data.max_score and .score > 0' "$tmp/reference.json" >/dev/null &&
    say "ok: the reference scores $got of $max" || bad "the reference scores $got of $max"
fi

grade stubs "$src/assignments/$stage" VL_GRADER_BWRAP=/nonexistent/bwrap || bad "run_autograder failed on the stubs: $(tail -n 5 "$tmp/stubs.log")"
if check stubs WEAKER; then
  [ "$(score .score stubs)" = 0 ] && say "ok: the stubs score 0, graded in the weaker sandbox, and the output says so" ||
    bad "the stubs score $(score .score stubs)"
  jq -r .output "$tmp/stubs.json" | grep -q "Not in force" || bad "the weaker sandbox's statement does not say what is not in force"
fi

case_dir=$src/grader/tests/submissions/$stage/$bug
cp -R "$src/reference/$stage" "$tmp/bug"
patch -s -p1 -d "$tmp/bug" -i "$case_dir/bug.patch" || bad "$case_dir/bug.patch does not apply to reference/$stage"
range=$(sed -n 's/^score_percent *= *\[ *\([0-9.]*\) *, *\([0-9.]*\) *\].*/\1 \2/p' "$case_dir/expected.toml")
read -r lo hi <<<"$range"
grade bug "$tmp/bug" || bad "run_autograder failed on $bug: $(tail -n 5 "$tmp/bug.log")"
if check bug bubblewrap && [ -n "$range" ]; then
  jq -e --argjson lo "$lo" --argjson hi "$hi" \
    '(.score / .extra_data.max_score * 100) as $p | $p >= $lo and $p <= $hi' "$tmp/bug.json" >/dev/null &&
    say "ok: $bug scores $(score .score bug) of $(score .extra_data.max_score bug), within [$lo, $hi] %" ||
    bad "$bug scores $(score .score bug) of $(score .extra_data.max_score bug), outside [$lo, $hi] %"
fi

# The grader itself fails: not the student's fault, no score earned, exit non-zero. The
# submission is one zip, which run_autograder hands to the grader as the archive it is.
cat >"$tmp/broken-grader" <<EOF
#!/bin/sh
printf '%s\n' "\$@" >"$tmp/broken-args"
echo "grader grade: the disk is full (a test of run_autograder)" >&2
exit 1
EOF
chmod +x "$tmp/broken-grader"
mkdir -p "$tmp/zipped"
(cd "$src/reference/$stage" && zip -q -r "$tmp/zipped/submission.zip" .)
if grade broken "$tmp/zipped" VL_AUTOGRADER_GRADER="$tmp/broken-grader"; then
  bad "run_autograder exited 0 when the grader failed"
elif ! jq -e '.score == 0 and .extra_data.autograder_failed == true and ([.tests[].score] | add) == 0 and
              (.output | test("no fault of yours")) and (.output | test("the disk is full"))' "$tmp/broken.json" >/dev/null 2>&1; then
  bad "a failed grader: results.json does not say so: $(cat "$tmp/broken.json" 2>/dev/null)"
else
  say "ok: a failed grader exits non-zero and results.json says the autograder failed, with its message"
fi
# The real grader refusing: VL_AUTOGRADER_SANDBOX=bubblewrap on a machine without bubblewrap.
if grade refused "$src/reference/$stage" VL_GRADER_BWRAP=/nonexistent/bwrap VL_AUTOGRADER_SANDBOX=bubblewrap; then
  bad "run_autograder graded without bubblewrap although VL_AUTOGRADER_SANDBOX=bubblewrap"
elif ! jq -e '.score == 0 and .extra_data.autograder_failed == true and (.output | test("no fault of yours")) and
              (.output | test("bubblewrap"))' "$tmp/refused.json" >/dev/null 2>&1; then
  bad "the grader's refusal: results.json does not carry it: $(cat "$tmp/refused.json" 2>/dev/null)"
else
  say "ok: the grader's own refusal (no bubblewrap) reaches results.json as the autograder's failure"
fi
[ "$(sed -n 3p "$tmp/broken-args" 2>/dev/null)" = "$ag/submission/submission.zip" ] ||
  bad "a submission of one zip was not graded as that zip: the grader got $(tr '\n' ' ' <"$tmp/broken-args" 2>/dev/null)"

say "wall time: $((SECONDS - start)) s"
[ $fail -eq 0 ] && echo "the Gradescope bundle: all as expected"
exit $fail
