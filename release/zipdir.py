#!/usr/bin/env python3
"""Writes a reproducible zip of a folder: zipdir.py OUT.zip ROOT

Every file and folder under ROOT goes in, named relative to ROOT, in sorted order, deflated, dated
1980-01-01 (the zip format's epoch, so the same files give the same bytes and the same SHA256SUMS
line), with Unix permissions kept as 0755 for executables and 0644 otherwise: macOS's Archive
Utility and Info-ZIP's unzip restore them, so `dformer` and the `.command` installers stay runnable.
"""
import os
import stat
import sys
import zipfile

EPOCH = (1980, 1, 1, 0, 0, 0)


def entry(name, mode, is_dir):
    info = zipfile.ZipInfo(name + ("/" if is_dir else ""), EPOCH)
    perm = 0o755 if is_dir or mode & stat.S_IXUSR else 0o644
    info.external_attr = ((stat.S_IFDIR if is_dir else stat.S_IFREG) | perm) << 16
    if is_dir:
        info.external_attr |= 0x10  # MS-DOS directory flag
    info.create_system = 3  # Unix, so the permissions above are read
    info.compress_type = zipfile.ZIP_STORED if is_dir else zipfile.ZIP_DEFLATED
    return info


def main(out, root):
    paths = []
    for here, dirs, files in os.walk(root):
        for d in dirs:
            paths.append(os.path.join(here, d))
        for f in files:
            paths.append(os.path.join(here, f))
    with zipfile.ZipFile(out, "w") as z:
        for path in sorted(paths, key=lambda p: os.path.relpath(p, root).split(os.sep)):
            name = os.path.relpath(path, root).replace(os.sep, "/")
            st = os.stat(path)
            is_dir = stat.S_ISDIR(st.st_mode)
            if is_dir:
                z.writestr(entry(name, st.st_mode, True), b"")
            else:
                with open(path, "rb") as fh:
                    z.writestr(entry(name, st.st_mode, False), fh.read(), compresslevel=9)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: zipdir.py OUT.zip ROOT")
    main(sys.argv[1], sys.argv[2])
