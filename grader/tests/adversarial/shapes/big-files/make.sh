#!/bin/bash
# ADVERSARIAL shapes/big-files: a tar.gz of the stubs and 20 files of 60 MiB each (each under a 64 MiB file limit, 1.2 GiB together)
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
import gzip
def member(name, data=b'', size=None):  # a tar header (and data) for one regular file
    info = tarfile.TarInfo(name)
    info.size = len(data) if size is None else size
    return info.tobuf(tarfile.GNU_FORMAT) + data + bytes(-len(data) % 512)
def stub_members(prefix):
    return b''.join(member(prefix + f, open(os.path.join(stubs, f), 'rb').read())
                    for f in sorted(os.listdir(stubs)) if f.endswith(('.cc', '.hh')))
# gzip members may follow one another: the zeros are compressed once and written many times.
zeros = gzip.compress(bytes(60 << 20), 9, mtime=0)  # 60 MiB of zeros
with open(out, 'wb') as f:
    f.write(gzip.compress(stub_members('02-sphere/'), mtime=0))
    for k in range(1, 21):
        f.write(gzip.compress(member('02-sphere/padding-%d.bin' % k, size=60 << 20), mtime=0))
        f.write(zeros)
    f.write(gzip.compress(bytes(1024), mtime=0))
EOF
