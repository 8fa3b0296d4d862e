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
