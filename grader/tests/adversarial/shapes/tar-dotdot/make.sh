#!/bin/bash
# ADVERSARIAL shapes/tar-dotdot: a tar.gz of the stubs with members named ../../../../tmp/... and /tmp/...
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
import io
with tarfile.open(out, 'w:gz') as t:
    add_stubs(t, '02-sphere/')
    for name in ['../../../../../../../../../../tmp/vl-adversarial-tar-dotdot.cc', '/tmp/vl-adversarial-tar-absolute.cc',
                 '02-sphere/../../../../../../../../../../tmp/vl-adversarial-tar-inner.cc']:
        data = b'// must not land in /tmp\n'
        info = tarfile.TarInfo(name)
        info.size = len(data)
        t.addfile(info, io.BytesIO(data))
EOF
