#!/bin/bash
# ADVERSARIAL shapes/folder-file-symlinks: a folder submission of the stubs in which sphere.cc, plane.cc, triangle.cc and polygon.cc are symlinks to the reference's
# Usage: make.sh REPO_ROOT OUT   writes the submission (a folder) at OUT; nothing else is touched.
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
stage_files "$out/02-sphere"
for f in sphere plane triangle polygon; do
    ln -sf "$root/reference/02-sphere/$f.cc" "$out/02-sphere/$f.cc"
done
