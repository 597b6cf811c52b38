#!/bin/bash
# ADVERSARIAL shapes/zip-symlink-member: a zip of the stubs whose sphere.cc is a symlink member to the reference's, with a symlink member to / beside it
# Usage: make.sh REPO_ROOT OUT   writes the submission (a .zip) at OUT; nothing else is touched.
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
stage_files "$work/02-sphere"
ln -sf "$root/reference/02-sphere/sphere.cc" "$work/02-sphere/sphere.cc"
ln -s / "$work/02-sphere/outside"
(cd "$work" && zip -q -y -r "$out" 02-sphere)
