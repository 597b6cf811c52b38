#!/usr/bin/env bash
# The grade's measures, end to end (ctest label `grader`):
#   grader/tests/measures_test.sh GRADER RT SOURCE_DIR
# - the reference's grade of stage 01 charts every sweep (an SVG inlined per sweep, the
#   PNG beside it), shows four images per scene (submission, reference, FLIP map,
#   highlighted difference) and records each scene's FLIP mean in results.json;
# - a planted bug that shifts the camera by half a pixel fails the scene on FLIP and no sweep;
# - calibrate-thresholds measures every scene of the rubric;
# - rt --seed: seed 0 is the default image, another seed draws other samples.
set -uo pipefail
grader=$1 rt=$2 src=$3
fail=0
say() { echo "ok: $*"; }
bad() { echo "FAILED: $*"; fail=1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"

out="$work/reference"
if ! "$grader" grade 01 "$src/reference/01-tuples" --out "$out" >"$work/grade.log" 2>&1; then
  bad "grading the reference failed:"; cat "$work/grade.log"
else
  sweeps=$(grep -c '^\[\[sweep\]\]' "$src/grader/hidden/01-tuples/rubric.toml")
  scenes=$(grep -c '^\[\[scene\]\]' "$src/grader/hidden/01-tuples/rubric.toml")
  svgs=$(grep -o '<div class="chart"><svg' "$out/report.html" | wc -l)
  pngs=$(ls "$out"/charts/*.png 2>/dev/null | wc -l)
  [ "$sweeps" -ge 2 ] && [ "$svgs" -ge "$sweeps" ] && [ "$pngs" -ge "$sweeps" ] &&
    say "$sweeps sweeps, $svgs charts inlined, $pngs PNGs" || bad "sweeps $sweeps, inlined charts $svgs, PNGs $pngs"
  for caption in "this submission" "reference" "FLIP error" "differences in red"; do
    n=$(grep -o "<figcaption>$caption" "$out/report.html" | wc -l)
    [ "$n" -eq "$scenes" ] && say "$scenes scenes show '$caption'" || bad "'$caption' shown $n times for $scenes scenes"
  done
  n=$(grep -o '"flip_mean"' "$out/results.json" | wc -l)
  [ "$n" -eq "$scenes" ] && say "results.json has the FLIP mean of each of $scenes scenes" || bad "$n flip_mean for $scenes scenes"
  grep -q "classList.toggle('big')" "$out/report.html" && say "the images enlarge on a click" || bad "no click to enlarge"
fi

out="$work/half-pixel"
"$grader" calibrate "$src/grader/tests/submissions/01-tuples/camera-half-pixel" --out "$out" >"$work/half.log" 2>&1
if ! grep -q "as expected" "$work/half.log"; then
  bad "the half-pixel camera case is not as expected:"; tail -5 "$work/half.log"
elif ! python3 - "$out/results.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
scenes = [t for t in r["tests"] if "scene" in t.get("extra_data", {})]
sweeps = [t for t in r["tests"] if "sweep" in t.get("extra_data", {})]
failed = [t for t in scenes if t["status"] != "passed"]
assert failed and all("FLIP mean" in t["output"] for t in failed), "no scene fails on FLIP"
assert sweeps and all(t["status"] == "passed" for t in sweeps), "a sweep fails"
PY
then
  bad "the half-pixel camera: a scene should fail on FLIP and every sweep pass"
else
  say "a half-pixel camera fails scenes on FLIP and passes every sweep"
fi

if "$grader" calibrate-thresholds 01 --out "$work/thresholds" >"$work/thr.log" 2>&1; then
  n=$(grep -c ' spread: ' "$work/thr.log")
  [ "$n" -eq "$(grep -c '^\[\[scene\]\]' "$src/grader/hidden/01-tuples/rubric.toml")" ] &&
    say "calibrate-thresholds measured $n scenes" || bad "calibrate-thresholds measured $n scenes"
else
  bad "calibrate-thresholds failed:"; cat "$work/thr.log"
fi

scene="$src/assignments/01-tuples/scenes/sky.ray_trace"
"$rt" "$scene" -o "$work/s0.png" --size 32x24 --spp 4 --sampler jittered --threads 1 >/dev/null 2>&1
"$rt" "$scene" -o "$work/d.png" --size 32x24 --spp 4 --sampler jittered --threads 1 --seed 0 >/dev/null 2>&1
"$rt" "$scene" -o "$work/s1.png" --size 32x24 --spp 4 --sampler jittered --threads 2 --seed 1 >/dev/null 2>&1
"$rt" "$scene" -o "$work/s1b.png" --size 32x24 --spp 4 --sampler jittered --threads 1 --seed 1 >/dev/null 2>&1
if cmp -s "$work/s0.png" "$work/d.png" && cmp -s "$work/s1.png" "$work/s1b.png" && ! cmp -s "$work/s0.png" "$work/s1.png"; then
  say "rt --seed: 0 is the default, 1 differs, and is the same on any thread count"
else
  bad "rt --seed does not behave"
fi
exit $fail
