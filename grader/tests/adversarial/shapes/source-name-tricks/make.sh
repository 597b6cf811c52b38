#!/bin/bash
# ADVERSARIAL shapes/source-name-tricks: a folder of the stubs plus source files whose names are shell and CMake syntax ($(...), `...`, ;, -o, quotes, a newline)
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
for name in '$(touch vl-adversarial-pwned).cc' '`touch vl-adversarial-pwned`.cc' 'a;b.cc' '-o.cc' \
            '"quote.cc' "it's.cc" $'new\nline.cc' '${HOME}.cc'; do
    printf '// ADVERSARIAL: a file name that is shell or CMake syntax\n' > "$out/02-sphere/$name"
done
