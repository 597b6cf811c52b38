#!/usr/bin/env bash
# The grader's own failures are its own (ctest label `grader`):
#   grader/tests/own_failures.sh GRADER SOURCE_DIR [STAGE...]
# - grading into a fresh `mktemp -d` folder (mode 0700) scores the reference 100 for every
#   stage (or the STAGEs named: the sanitizer build names one, as its calibration grades
#   every stage's reference already);
# - an --out the grader cannot write, or a machine without bubblewrap, makes it exit
#   non-zero naming the cause, and writes no results.json that scores anyone;
# - with --weaker-sandbox it grades anyway, and the results say the sandbox was weaker;
# - a program that ends as a sandbox that cannot start ends is still the student's outcome.
set -uo pipefail
grader=$1 src=$2
shift 2
fail=0
say() { echo "$*"; }
bad() { echo "FAILED: $*"; fail=1; }

stages=("$@")
[ ${#stages[@]} -gt 0 ] || mapfile -t stages < <("$grader" list | awk '{print $1}')
for stage in "${stages[@]}"; do
  out="$(mktemp -d)/x"
  if "$grader" grade "$stage" "$src/reference/$stage" --out "$out" >"$out.log" 2>&1 &&
     grep -q '"score": 100.0' "$out/results.json"; then
    say "ok: $stage reference scores 100 in a 0700 mktemp folder"
  else
    bad "$stage reference in a 0700 mktemp folder:"; cat "$out.log"
  fi
  rm -rf "$(dirname "$out")"
done

stage=$("$grader" list | awk 'NR==1 {print $1}')
blocked=$(mktemp -d)
touch "$blocked/file"
if "$grader" grade "$stage" "$src/reference/$stage" --out "$blocked/file/out" >"$blocked/log" 2>&1; then
  bad "an --out under a file was accepted"
elif ! grep -q "cannot write results to" "$blocked/log"; then
  bad "an unwritable --out: the message does not say so:"; cat "$blocked/log"
else
  say "ok: an unwritable --out exits non-zero: $(head -c 200 "$blocked/log")"
fi

out="$blocked/no-bwrap"
if VL_GRADER_BWRAP=/nonexistent/bwrap "$grader" grade "$stage" "$src/reference/$stage" --out "$out" >"$blocked/log2" 2>&1; then
  bad "graded without bubblewrap and without --weaker-sandbox"
elif [ -e "$out/results.json" ]; then
  bad "wrote $out/results.json although it could not grade"
elif ! grep -q "bubblewrap" "$blocked/log2" || ! grep -q -- "--weaker-sandbox" "$blocked/log2"; then
  bad "without bubblewrap: the message does not name the cause and the way out:"; cat "$blocked/log2"
else
  say "ok: without bubblewrap it refuses: $(head -c 160 "$blocked/log2")"
fi

if VL_GRADER_BWRAP=/nonexistent/bwrap "$grader" grade "$stage" "$src/reference/$stage" --out "$out" --weaker-sandbox \
     >"$blocked/log3" 2>&1 && grep -q '"score": 100.0' "$out/results.json" && grep -q 'WEAKER SANDBOX' "$out/results.json" &&
   grep -q 'WEAKER SANDBOX' "$out/report.html"; then
  say "ok: --weaker-sandbox grades the reference 100 and says so in results.json and report.html"
else
  bad "--weaker-sandbox:"; cat "$blocked/log3"
fi
# A program that ends as a sandbox that cannot start ends (status 125, "sandbox: ..." on
# stderr) is the student's outcome in the weaker sandbox too, never the grader's failure.
imitation="$src/grader/tests/adversarial/01-tuples/imitate-sandbox-failure"
if [ -d "$imitation" ] && "$grader" list | grep -q '^01-tuples'; then
  if VL_GRADER_BWRAP=/nonexistent/bwrap "$grader" calibrate "$imitation" --no-policy --weaker-sandbox \
       --out "$blocked/imitation" >"$blocked/log4" 2>&1 && grep -q "as expected" "$blocked/log4"; then
    say "ok: in the weaker sandbox, a program that imitates a sandbox failing to start is graded as the student's"
  else
    bad "a program that imitates a sandbox failing to start, in the weaker sandbox:"; cat "$blocked/log4"
  fi
fi
rm -rf "$blocked"
[ $fail -eq 0 ] && echo "the grader's own failures: all as expected"
exit $fail
