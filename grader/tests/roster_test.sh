#!/usr/bin/env bash
# The roster (ctest label `grader`):
#   grader/tests/roster_test.sh GRADER SOURCE_DIR
# - 20 submissions of 02 (the reference as folders and archives, the stubs, planted bugs
#   of the calibration, a correct alternative, an archive that is no archive) get the
#   scores their expected.toml says, and copies the same score;
# - killed with SIGKILL midway, the roster leaves no grade running; run again, it grades
#   only who has no result, and ends with every result present exactly once;
# - --regrade grades the named one again; a changed submission is graded again alone;
# - a second roster into the same folder is refused while the first runs;
# - when the grader itself fails, nobody gets a score, and a rerun grades them;
# - roster-collect writes the same CSV again.
set -uo pipefail
grader=$1 src=$2
cases=$src/grader/tests/submissions/02-sphere
fail=0
bad() { echo "FAILED: $*"; fail=1; }
ok() { echo "ok: $*"; }
tmp=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$tmp"' EXIT
dir=$tmp/submissions out=$tmp/out
mkdir -p "$dir"

# NAME CASE [kind]: the calibration case CASE as NAME (a folder, or kind tgz or zip).
add() {
  local name=$1 case=$2 kind=${3:-folder} copy=$tmp/made/$1/02-sphere
  mkdir -p "$copy"
  case $case in
    reference) cp "$src"/reference/02-sphere/*.cc "$src"/reference/02-sphere/*.hh "$copy"/ 2>/dev/null ;;
    stubs) cp -r "$src"/assignments/02-sphere/. "$copy"/ ;;
    *) if [ -f "$cases/$case/bug.patch" ]; then
         cp "$src"/reference/02-sphere/*.cc "$src"/reference/02-sphere/*.hh "$copy"/ 2>/dev/null
         patch --batch --silent -p1 -d "$copy" -i "$cases/$case/bug.patch" || { bad "$case: bug.patch does not apply"; return; }
       else
         cp "$cases/$case"/*.cc "$cases/$case"/*.hh "$copy"/
       fi ;;
  esac
  case $kind in
    folder) cp -r "$copy" "$dir/$name" ;;
    tgz) tar -czf "$dir/$name.tar.gz" -C "$(dirname "$copy")" 02-sphere ;;
    zip) (cd "$(dirname "$copy")" && zip -qr "$dir/$name.zip" 02-sphere) ;;
  esac
  echo "$name $case" >>"$tmp/cast"
}
for n in alice bob carol dave; do add $n reference; done
add erin reference tgz
add frank reference zip
add gina stubs
add hal stubs
add ivan inward-normal
add judy inward-normal tgz
add kim inside-misses
add leo plane-behind-abs
add mia crash-contains
add ned compile-error
add olga textbook-quadratic
add pat sphere-normal-not-unit
add quinn triangle-backface-cull
add rosa polygon-fan-gaps
add sam alt-unit-sphere-perp
echo "this is no zip archive" >"$dir/tom.zip"
echo "tom broken-archive" >>"$tmp/cast"
echo "notes for the TA" >"$dir/notes.txt"
[ "$(ls "$dir" | wc -l)" -eq 21 ] || bad "the roster folder should hold 20 submissions and a note: $(ls "$dir")"

# Run 1, killed with SIGKILL once at least 6 results are in.
"$grader" roster 02 "$dir" --out "$out" -j 2 >"$tmp/run1.log" 2>&1 &
roster=$!
for _ in $(seq 1 600); do
  [ "$(ls "$out/results" 2>/dev/null | grep -c '\.json$')" -ge 6 ] && break
  kill -0 $roster 2>/dev/null || break
  sleep 0.2
done
kill -9 $roster 2>/dev/null
wait $roster 2>/dev/null
before=$(ls "$out/results" | grep -c '\.json$')
sleep 1
if pgrep -f "grade 02-sphere $dir/" >/dev/null; then bad "grades still run after the roster was killed: $(pgrep -af "grade 02-sphere $dir/")"
else ok "killed after $before results; no grade runs on without it"; fi
[ "$before" -lt 20 ] || bad "the roster finished before it could be killed (the test needs it killed midway)"

# Run 2 finishes the job: it grades only those without a result.
if ! "$grader" roster 02 "$dir" --out "$out" -j 2 >"$tmp/run2.log" 2>&1; then bad "the rerun failed:"; cat "$tmp/run2.log"; fi
grep -q "skipped notes.txt" "$tmp/run2.log" || bad "the rerun does not say it skipped notes.txt"
if grep -q "; $before already graded and unchanged; grading $((20 - before)) with" "$tmp/run2.log"; then
  ok "the rerun kept the $before results and graded the other $((20 - before))"
else bad "the rerun did not grade exactly the $((20 - before)) missing:"; head -3 "$tmp/run2.log"; fi
csv=$out/roster.csv
rows=$(tail -n +2 "$csv" | wc -l)
[ "$rows" -eq 20 ] || bad "roster.csv has $rows rows, not 20"
[ "$(tail -n +2 "$csv" | cut -d, -f1 | sort | uniq -d | wc -l)" -eq 0 ] || bad "a student is in roster.csv twice"
[ "$(ls "$out/results" | grep -c '\.json$')" -eq 20 ] || bad "results/ holds $(ls "$out/results") , not 20 records"
[ "$(ls "$out/grades" | wc -l)" -eq 20 ] || bad "grades/ holds $(ls "$out/grades" | wc -l) grades, not 20"
[ -z "$(ls "$out/.work" | grep -v '\.lock$')" ] || bad "a grade under way was left in .work: $(ls "$out/.work")"

# Every score in its calibration case's range; copies score the same.
python3 - "$csv" "$tmp/cast" "$cases" <<'EOF' || fail=1
import csv, sys, tomllib
rows = {r["student"]: r for r in csv.DictReader(open(sys.argv[1], newline=""))}
problems = []
by_case = {}
for line in open(sys.argv[2]):
    name, case = line.split()
    r = rows.get(name)
    if r is None:
        problems.append(f"{name} is not in roster.csv"); continue
    if case == "broken-archive":
        lo, hi, built = 0, 0, False
    elif case in ("reference",):
        lo, hi, built = 100, 100, True
    else:
        e = tomllib.load(open(f"{sys.argv[3]}/{case}/expected.toml", "rb"))
        lo, hi = e["score_percent"]
        built = e.get("built", True)
    p = float(r["percent"])
    if not lo - 1e-6 <= p <= hi + 1e-6:
        problems.append(f"{name} ({case}) scored {p}%, expected {lo}..{hi}")
    if (r["verdict"] == "graded") != built:
        problems.append(f"{name} ({case}): verdict {r['verdict']}, expected built={built}")
    by_case.setdefault(case, set()).add(r["score"])
for case, scores in by_case.items():
    if len(scores) > 1: problems.append(f"copies of {case} scored differently: {sorted(scores)}")
for p in problems: print("FAILED:", p)
if not problems: print("ok: all 20 scores in their expected ranges, copies alike")
sys.exit(1 if problems else 0)
EOF

# A rerun with nothing changed grades nobody.
"$grader" roster 02 "$dir" --out "$out" -j 2 >"$tmp/run3.log" 2>&1 || bad "a rerun with nothing to do failed"
grep -q "; 20 already graded and unchanged; grading 0 with" "$tmp/run3.log" && ok "a rerun with nothing new grades nobody" ||
  { bad "a rerun with nothing new:"; head -3 "$tmp/run3.log"; }
cp "$csv" "$tmp/roster-before.csv"

# --regrade grades the named ones again, and only them.
"$grader" roster 02 "$dir" --out "$out" --regrade alice gina >"$tmp/run4.log" 2>&1 || bad "--regrade failed"
grep -q "; 18 already graded and unchanged; grading 2 with" "$tmp/run4.log" && cmp -s "$csv" "$tmp/roster-before.csv" &&
  ok "--regrade alice gina grades those two again, with the same result" || { bad "--regrade:"; cat "$tmp/run4.log"; }
"$grader" roster 02 "$dir" --out "$out" --regrade nobody >"$tmp/run5.log" 2>&1 && bad "--regrade of an unknown name was accepted"
grep -q "has no submission of that name" "$tmp/run5.log" || { bad "--regrade nobody: the message:"; cat "$tmp/run5.log"; }

# A record made by another build of the grader (or another rubric) is graded again.
python3 - "$out/results/carol.json" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1])); r["setup"] = "0000000000000000"; json.dump(r, open(sys.argv[1], "w"))
EOF
"$grader" roster 02 "$dir" --out "$out" >"$tmp/run4b.log" 2>&1 || bad "the rerun after another build failed"
grep -q "; 19 already graded and unchanged; grading 1 with" "$tmp/run4b.log" &&
  grep -q "of them, 1 had been graded by another build of the grader" "$tmp/run4b.log" &&
  ok "a grade from another build of the grader is graded again" || { bad "another build's grade:"; cat "$tmp/run4b.log"; }

# A changed submission is graded again, alone: bob breaks his sphere.
patch --batch --silent -p1 -d "$dir/bob" -i "$cases/inward-normal/bug.patch" || bad "cannot change bob's submission"
"$grader" roster 02 "$dir" --out "$out" >"$tmp/run6.log" 2>&1 || bad "the rerun after a change failed"
bob=$(grep '^"bob",' "$csv" | cut -d, -f3)
grep -q "; 19 already graded and unchanged; grading 1 with" "$tmp/run6.log" && [ "$bob" != 100 ] &&
  ok "bob's changed submission alone was graded again ($bob points now)" || { bad "a changed submission:"; cat "$tmp/run6.log"; }
[ "$(ls "$out/grades" | grep -c '^bob-')" -eq 1 ] || bad "bob's old grade was not cleared: $(ls "$out/grades")"

# Two rosters into one folder: the second is refused while the first runs.
"$grader" roster 02 "$dir" --out "$out" --regrade carol dave >"$tmp/run7.log" 2>&1 &
first=$!
for _ in $(seq 1 100); do ls "$out/.work" | grep -q '^shard-0-of-1$' && break; sleep 0.1; done
if "$grader" roster 02 "$dir" --out "$out" >"$tmp/run8.log" 2>&1; then bad "a second roster into the same --out was not refused"
elif grep -q "another roster is grading into" "$tmp/run8.log"; then ok "a second roster into the same folder is refused"
else bad "a second roster: the message:"; cat "$tmp/run8.log"; fi
wait $first || bad "the first roster of the two failed"

# The CSV: roster-collect makes the same file again; the cells are quoted as RFC 4180 says.
cp "$csv" "$tmp/roster-after.csv"
"$grader" roster-collect "$out" >"$tmp/collect.log" 2>&1 || { bad "roster-collect failed:"; cat "$tmp/collect.log"; }
cmp -s "$csv" "$tmp/roster-after.csv" && ok "roster-collect writes the same roster.csv" || bad "roster-collect wrote another CSV"
head -1 "$csv" | grep -q '^"student","verdict","score","max_score","percent","sphere","planes","triangles","polygons","passed",' ||
  bad "roster.csv's header: $(head -1 "$csv")"

# The grader fails (no bubblewrap and no --weaker-sandbox): no score for anyone; a rerun grades them.
small=$tmp/small
mkdir -p "$small"
cp -r "$dir/alice" "$dir/gina" "$small"/
if VL_GRADER_BWRAP=/nonexistent/bwrap "$grader" roster 02 "$small" --out "$tmp/out2" >"$tmp/run9.log" 2>&1; then
  bad "a roster whose grades all failed exited 0"
fi
if grep -q '^"alice","grader error",,,' "$tmp/out2/roster.csv" && grep -q "GRADER ERROR" "$tmp/run9.log" &&
   grep -q "the grader failed, not the student" "$tmp/run9.log"; then
  ok "when the grader fails, the CSV says grader error and gives no score"
else bad "a grader failure:"; cat "$tmp/run9.log" "$tmp/out2/roster.csv"; fi
"$grader" roster 02 "$small" --out "$tmp/out2" >"$tmp/run10.log" 2>&1 && grep -q '^"alice","graded",100,' "$tmp/out2/roster.csv" &&
  ok "the rerun grades those the grader failed" || { bad "the rerun after a grader failure:"; cat "$tmp/run10.log"; }

[ $fail -eq 0 ] && echo "the roster: all as expected"
exit $fail
