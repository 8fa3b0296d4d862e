"""Scratch copies of case folders: a benchmark, a test or a utility runs a
tutorial's inputs in a folder of its own, so that running never touches
the tracked case (and meshes made there are made again)."""

import os
import shutil


def copyInputs(src, dst, names, ignore=()):
    """Copy the entries `names` (folders and files) of the case src into
    the new folder dst, without what matches a pattern of ignore at any
    depth (meshes that the case's Allrun makes again)."""
    os.makedirs(dst)
    for name in names:
        s = os.path.join(src, name)
        if os.path.isdir(s):
            shutil.copytree(s, os.path.join(dst, name),
                            ignore=shutil.ignore_patterns(*ignore))
        else:
            shutil.copy(s, dst)


def main(argv=None):
    """Command line for shell scripts: python3 -m neuronFsi.scratch SRC DST
    NAME... [--ignore PATTERN...]"""
    import argparse
    p = argparse.ArgumentParser(
        prog="python3 -m neuronFsi.scratch",
        description="Copy a case's inputs into a new scratch folder.")
    p.add_argument("src", help="the case folder to copy from")
    p.add_argument("dst", help="the new folder (must not exist)")
    p.add_argument("names", nargs="+",
                   help="entries of src to copy (e.g. 0.orig constant system Allrun)")
    p.add_argument("--ignore", nargs="*", default=(),
                   help="patterns left out at any depth (e.g. polyMesh '*.msh')")
    a = p.parse_args(argv)
    if os.path.exists(a.dst):
        p.error("%s exists: give a new folder" % a.dst)
    for name in a.names:
        if not os.path.exists(os.path.join(a.src, name)):
            p.error("%s has no %s" % (a.src, name))
    copyInputs(a.src, a.dst, a.names, a.ignore)


if __name__ == "__main__":
    main()
