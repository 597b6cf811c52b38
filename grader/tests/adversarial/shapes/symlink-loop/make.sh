#!/bin/bash
# ADVERSARIAL shapes/symlink-loop: a tar.gz of the stubs with symlinks that loop (self -> ., up -> .., loop -> loop) inside the stage folder
# Usage: make.sh REPO_ROOT OUT   writes the submission (a .tar.gz) at OUT; nothing else is touched.
set -euo pipefail
root=$(cd "$1" && pwd)
out=$(realpath -m "$2")
stubs="$root/assignments/02-sphere"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stage_files() {  # the untouched stubs of stage 02 (its .cc and .hh files) into folder $1
    mkdir -p "$1"
    cp "$stubs"/*.cc "$stubs"/*.hh "$1"/
}
stage_files "$work/kit/assignments/02-sphere"
ln -s . "$work/kit/assignments/02-sphere/self"
ln -s .. "$work/kit/assignments/02-sphere/up"
ln -s loop "$work/kit/assignments/02-sphere/loop"
ln -s loop.cc "$work/kit/assignments/02-sphere/loop.cc"
tar -czf "$out" -C "$work/kit" assignments
