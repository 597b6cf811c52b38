#!/bin/bash
# ADVERSARIAL shapes/tar-hardlink-outside: a tar.gz of the stubs whose sphere.cc is a hard link member to the reference's sphere.cc (absolute and ../ link names)
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
with tarfile.open(out, 'w:gz') as t:
    for f in sorted(os.listdir(stubs)):
        if f.endswith(('.cc', '.hh')) and f not in ('sphere.cc', 'plane.cc'):
            t.add(os.path.join(stubs, f), '02-sphere/' + f)
    for name, target in [('02-sphere/sphere.cc', root + '/reference/02-sphere/sphere.cc'),
                         ('02-sphere/plane.cc', '../' * 40 + root.lstrip('/') + '/reference/02-sphere/plane.cc')]:
        info = tarfile.TarInfo(name)
        info.type = tarfile.LNKTYPE
        info.linkname = target
        t.addfile(info)
EOF
