#!/bin/bash
# ADVERSARIAL shapes/tar-sparse-bomb: a tiny tar.gz (GNU sparse member) of the stubs and one file of 16 GiB, nearly all hole
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
stage_files "$work/02-sphere"
truncate -s 16G "$work/02-sphere/padding.bin"
tar --sparse -czf "$out" -C "$work" 02-sphere
