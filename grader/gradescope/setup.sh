#!/usr/bin/env bash
# setup.sh — a Gradescope bundle's build step (grader/README.md, "Gradescope"). `grader/run
# gradescope ASSIGNMENT OUT.zip` puts it at the top of the bundle; Gradescope unpacks the
# bundle into /autograder/source and runs this once, as root, when it builds the
# autograder's image.
#
# It installs the Debian/Ubuntu packages (tools/setup: only the missing ones) and builds
# what grading the bundle's assignment needs (preset `grader`, target vl_grader_parts_NN)
# in build/grader beside it; then it checks that the grader it built can grade the
# assignment. Any failure ends it non-zero with a message that says what to do, so
# Gradescope shows the image's build as failed instead of grading with a broken autograder.
set -uo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
conf=$source_dir/autograder.conf
fail() {
  echo >&2
  echo "setup.sh: FAILED: $*" >&2
  echo "setup.sh: the autograder is not ready; no submission can be graded until the bundle is fixed and" \
       "uploaded again (grader/README.md, \"Gradescope\")." >&2
  exit 1
}

[ -f "$conf" ] || fail "$conf is missing: this is not a whole bundle; make it again with grader/run gradescope ASSIGNMENT OUT.zip"
assignment=$(sed -n 's/^assignment=//p' "$conf")
number=$(sed -n 's/^number=//p' "$conf")
[ -n "$assignment" ] && [ -n "$number" ] ||
  fail "$conf names no assignment (lines assignment=NN-name and number=NN): make the bundle again"
echo "setup.sh: building the autograder for $assignment in $source_dir/build/grader"
# An unpacker that drops the modes must not stop the grading step.
chmod +x "$source_dir/run_autograder" 2>/dev/null
if [ -f "$source_dir/../run_autograder" ]; then chmod +x "$source_dir/../run_autograder" 2>/dev/null; fi

# Packages first, on their own, so that a missing one is named before any build starts.
bash "$source_dir/tools/setup" --no-build ||
  fail "tools/setup could not install the packages (its messages are above): choose a base image whose" \
       "package manager has them (the Ubuntu image Gradescope offers, as grader/README.md says), or install them" \
       "in setup.sh before tools/setup runs"
cmake_version=$(cmake --version 2>/dev/null | sed -n 's/^cmake version \([0-9][0-9.]*\).*/\1/p')
if [ -z "$cmake_version" ] || ! printf '3.25\n%s\n' "$cmake_version" | sort -V -C; then
  fail "this image's CMake is ${cmake_version:-missing}; the project needs CMake 3.25 or newer" \
       "(CMakePresets.json version 6): choose a newer base image, or install a newer CMake in setup.sh before" \
       "tools/setup runs"
fi
catch2_version=$(dpkg-query -W -f='${Version}' catch2 2>/dev/null)
case "$catch2_version" in
  2.*) ;;
  *) fail "this image's Catch2 (the package catch2) is ${catch2_version:-missing}; the tests need Catch2 2.13 or a" \
          "later 2.x (find_package(Catch2 2.13) in CMakeLists.txt): choose a base image that packages Catch2 2, or" \
          "install Catch2 2 in setup.sh before tools/setup runs" ;;
esac

# The build, from scratch the first time (CMake and Ninja make it incremental afterwards).
start=$SECONDS
bash "$source_dir/tools/setup" --preset grader --target "vl_grader_parts_$number" ||
  fail "building the grader for $assignment failed (the compiler's or CMake's messages are above). Build the" \
       "same commit on a Debian 12 machine with tools/setup --preset grader and check a grade with" \
       "grader/run grade $assignment reference/$assignment, then make the bundle again"
echo "setup.sh: built in $((SECONDS - start)) s"

grader=$source_dir/build/grader/grader/grader
[ -x "$grader" ] || fail "the build finished but $grader is missing: is VL_BUILD_GRADER ON in the preset grader?"
"$grader" list | awk '{print $1}' | grep -qx "$assignment" ||
  fail "the grader built here cannot grade $assignment (grader list says: $("$grader" list 2>&1 | tr '\n' ' '))"
echo "setup.sh: ready: /autograder/run_autograder grades each submission of $assignment with $grader"
