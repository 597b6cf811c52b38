#!/usr/bin/env bash
# `grader imgdiff` (ctest label `grader`):
#   grader/tests/imgdiff_test.sh GRADER
# - identical images print flip_mean=0 ssim=1 max_abs=0 and exit 0; --map writes a PNG of
#   the inputs' size;
# - a missing file, a file that is no image and images of different sizes exit 1 with a
#   message naming the file and what is wrong; a wrong command line exits 2 with the usage.
set -uo pipefail
grader=$1
fail=0
bad() { echo "FAILED: $*"; fail=1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# ppm W H BYTE FILE: a W x H binary PPM whose every sample is BYTE (octal escape).
ppm() {
  printf 'P6\n%d %d\n255\n' "$1" "$2" >"$4"
  head -c $(($1 * $2 * 3)) /dev/zero | tr '\0' "$3" >>"$4"
}
ppm 6 4 '\200' "$dir/gray.ppm"
ppm 6 4 '\210' "$dir/lighter.ppm"
ppm 4 6 '\200' "$dir/tall.ppm"
echo "not an image" >"$dir/notes.txt"

# expect CODE PATTERN ARGS...: runs imgdiff, checks its exit code and that its output matches.
expect() {
  local code=$1 pattern=$2
  shift 2
  "$grader" imgdiff "$@" >"$dir/out" 2>&1
  local got=$?
  if [ "$got" -ne "$code" ]; then
    bad "imgdiff $*: exit $got, expected $code:"; cat "$dir/out"
  elif ! grep -Eq -- "$pattern" "$dir/out"; then
    bad "imgdiff $*: the output does not match '$pattern':"; cat "$dir/out"
  else
    echo "ok: imgdiff $* -> $got: $(head -c 300 "$dir/out")"
  fi
}

expect 0 '^flip_mean=0\.000000 ssim=1\.000000 max_abs=0 ' "$dir/gray.ppm" "$dir/gray.ppm"
expect 0 '^flip_mean=0\.[0-9]+ ssim=0\.99[0-9]+ max_abs=8 flip_weighted_median=' "$dir/gray.ppm" "$dir/lighter.ppm" \
  --map "$dir/map.png"
# The map: a PNG whose IHDR says 6 x 4 (bytes 16-23: width and height, big-endian).
if [ "$(head -c 4 "$dir/map.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" != "89504e47" ]; then
  bad "--map did not write a PNG"
elif [ "$(od -An -tu1 -j16 -N8 "$dir/map.png" | tr -s ' ' | sed 's/^ //')" != "0 0 0 6 0 0 0 4" ]; then
  bad "--map wrote a PNG of another size: $(od -An -tu1 -j16 -N8 "$dir/map.png")"
else
  echo "ok: --map wrote a 6 x 4 PNG"
fi

expect 1 "cannot read the reference image: $dir/missing.png: cannot open" "$dir/missing.png" "$dir/gray.ppm"
expect 1 "cannot read the test image: $dir/missing.png: cannot open" "$dir/gray.ppm" "$dir/missing.png"
expect 1 "cannot read the test image: $dir/notes.txt: not an image" "$dir/gray.ppm" "$dir/notes.txt"
expect 1 "differ in size: the reference $dir/gray.ppm is 6 x 4 pixels and the test $dir/tall.ppm is 4 x 6 pixels" \
  "$dir/gray.ppm" "$dir/tall.ppm"
expect 1 "cannot write the error map: $dir/no/such/folder/map.png" "$dir/gray.ppm" "$dir/gray.ppm" \
  --map "$dir/no/such/folder/map.png"
expect 2 "expected 2 argument\(s\), got 1" "$dir/gray.ppm"
expect 2 "--ppd needs a positive number" "$dir/gray.ppm" "$dir/gray.ppm" --ppd -3
expect 2 "unknown option '--colour'" "$dir/gray.ppm" "$dir/gray.ppm" --colour
exit $fail
