#!/bin/bash
# ADVERSARIAL shapes/zip-dotdot: a zip of the stubs with members named ../../../../tmp/... and /tmp/... (zip slip)
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
python3 - "$root" "$out" "$stubs" <<'EOF'
import os, sys, zipfile
root, out, stubs = sys.argv[1:4]
def add_stubs(z, prefix):
    for f in sorted(os.listdir(stubs)):
        if f.endswith(('.cc', '.hh')):
            z.write(os.path.join(stubs, f), prefix + f)
with zipfile.ZipFile(out, 'w') as z:
    add_stubs(z, '02-sphere/')
    z.writestr('../../../../../../../../../../tmp/vl-adversarial-zip-dotdot.cc', '// must not land in /tmp\n')
    z.writestr('/tmp/vl-adversarial-zip-absolute.cc', '// must not land in /tmp\n')
    z.writestr('02-sphere/../../../../../../../../../../tmp/vl-adversarial-zip-inner.cc', '// must not land in /tmp\n')
EOF
