#!/bin/bash
# ADVERSARIAL shapes/many-files: a tar.gz of the stubs and 200,000 empty files
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
python3 - "$root" "$out" "$stubs" <<'EOF'
import os, sys, tarfile
root, out, stubs = sys.argv[1:4]
def add_stubs(t, prefix):
    for f in sorted(os.listdir(stubs)):
        if f.endswith(('.cc', '.hh')):
            t.add(os.path.join(stubs, f), prefix + f)
with tarfile.open(out, 'w:gz', compresslevel=9) as t:
    add_stubs(t, 'assignments/02-sphere/')
    for k in range(200000):
        info = tarfile.TarInfo('junk/%06d' % k)
        info.mtime = 0
        t.addfile(info)
EOF
