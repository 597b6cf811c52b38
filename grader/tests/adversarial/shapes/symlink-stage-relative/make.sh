#!/bin/bash
# ADVERSARIAL shapes/symlink-stage-relative: a kit whose assignments/02-sphere is a symlink to ../../reference/02-sphere
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
mkdir -p "$work/kit/assignments"
ln -s ../../reference/02-sphere "$work/kit/assignments/02-sphere"
tar -czf "$out" -C "$work/kit" assignments
