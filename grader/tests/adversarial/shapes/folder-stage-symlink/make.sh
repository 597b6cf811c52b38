#!/bin/bash
# ADVERSARIAL shapes/folder-stage-symlink: a folder submission whose assignments/02-sphere is a symlink to reference/02-sphere
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
mkdir -p "$out/assignments"
ln -s "$root/reference/02-sphere" "$out/assignments/02-sphere"
