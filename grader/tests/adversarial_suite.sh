#!/usr/bin/env bash
# The adversarial suite (grader/tests/adversarial/README.md), as ctest runs it:
#
#   adversarial_suite.sh GRADER OUT_DIR [-j N] [-s F] [CASE_DIR...]
#
# Grades every attack case (or the ones named) with `grader calibrate`, which checks its
# expected.toml (the score's range, the verdict, the results.json format), and again with
# --no-policy when expected.toml has a [sandbox] table, so the sandbox alone must hold it.
# N cases run at a time (default 2). Each grade has a time bound; with -s F, the rubric's
# test and render time limits are scaled by F (calibrate --limits-scale). Before and after the
# whole suite the checkout, the build tree (less the suite's own output) and /tmp (what a
# sandbox's user owns there, and anything named for an attack) are listed (path, size,
# mode, owner, mtime): any difference fails the suite and is shown.
# ctest runs this alone (RUN_SERIAL), so nothing else changes those folders meanwhile.
set -uo pipefail
grader=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$2
shift 2
jobs=2 scale=1
while [ $# -gt 0 ]; do
  case $1 in
    -j) jobs=$2; shift 2 ;;
    -s) scale=$2; shift 2 ;;
    *) break ;;
  esac
done
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
src=$(cd "$here/../.." && pwd)
build=$(cd "$(dirname "$grader")/.." && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)

manifest() {
  {
    find "$src" -path "$src/build" -prune -o -printf '%p %s %m %U %T@\n'
    find "$build" \( -path "$out" -o -path "$build/grader/calibration" -o -path "$build/grader/calibration-sources" \
      -o -path "$build/Testing" -o -path "$build/grader/kit-test" -o -path "$build/grader/compile-cache" \
      -o -name 'compile-cache-*.stamp' \) -prune -o -printf '%p %s %m %U %T@\n'
    # In /tmp, what an escaped sandbox would leave: files of the sandbox's user (nobody,
    # when the grader runs as root) and the attacks' own marks. The rest of /tmp belongs
    # to whatever else runs on the machine, which may change it meanwhile.
    find /tmp -xdev -maxdepth 4 -path "$out" -prune -o \( -user 65534 -o -name '*adversarial*' \) \
      -printf '%p %s %m %U\n' 2>/dev/null
  } | sort
}

if [ $# -gt 0 ]; then
  cases=("$@")
else
  mapfile -t cases < <(find "$here/adversarial" -mindepth 3 -maxdepth 3 -name expected.toml -printf '%h\n' | sort)
fi
runs=()
for c in "${cases[@]}"; do
  runs+=("$c")
  grep -q '^\[sandbox\]' "$c/expected.toml" && runs+=("$c --no-policy")
done

# Compile the stages' caches first, so every attack is timed on its own.
for stage in $("$grader" list | awk '{print $1}'); do
  "$grader" calibrate "$src/grader/tests/submissions/$stage/reference" --out "$out/warm-$stage" \
    --limits-scale "$scale" >/dev/null 2>&1
done

manifest >"$out/manifest.before"
one() {
  local case_dir=$1 flag=${2:-}
  local name
  name="$(basename "$(dirname "$case_dir")")/$(basename "$case_dir")${flag:+ (the sandbox alone)}"
  local dir="$out/$(basename "$(dirname "$case_dir")")-$(basename "$case_dir")${flag:+-sandbox}"
  local start=$SECONDS
  timeout --kill-after=10 600 "$grader" calibrate "$case_dir" --out "$dir" --limits-scale "$scale" --jobs 1 $flag >"$dir.log" 2>&1
  local status=$?
  local verdict="ok"
  [ $status -eq 0 ] || verdict="FAILED"
  [ $status -eq 124 ] || [ $status -eq 137 ] && verdict="FAILED (the grader did not finish in 600 s)"
  printf '%-8s %-72s %4ss\n' "$verdict" "$name" $((SECONDS - start))
  if [ $status -ne 0 ]; then grep -h 'CALIBRATION\|^grader' "$dir.log" | sed 's/^/         /' | head -8; fi
  return $status
}
export -f one
export grader out scale
printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c 'one {}' >"$out/results.txt"
status=$?
cat "$out/results.txt"
manifest >"$out/manifest.after"
if ! diff -q "$out/manifest.before" "$out/manifest.after" >/dev/null; then
  echo "FAILED: something outside the grades' own output changed:"
  diff "$out/manifest.before" "$out/manifest.after" | head -40
  status=1
fi
passed=$(grep -c '^ok ' "$out/results.txt")
failed=$(grep -c '^FAILED' "$out/results.txt")
echo "adversarial: ${#cases[@]} attacks, ${#runs[@]} grades"
echo "$passed passed, $failed failed"
# The failures again, last, where a log cut short still shows them.
[ "$failed" -eq 0 ] || grep -A8 '^FAILED' "$out/results.txt" | grep -v '^ok \|^--$' | sed 's/^/failed: /'
[ "$failed" -eq 0 ] && [ $status -eq 0 ]
