#!/usr/bin/env python3
"""make grade-deps: says when FLIP's venv is out of other users' reach. The venv runs the interpreter
it was made with (bin/python3, a link); one made from a Python under a folder no one else may enter
(pyenv under /root, a 0700 home), or a venv inside such a folder, runs only for its owner: a grader
run as another user then stops with "flip cannot be run ... Permission denied".

usage: flip_reach.py VENV     prints a note naming the folder when others cannot run it; exit 0 always."""
import os
import stat
import sys


def closed_folder(path):
    """The first folder on the way to `path` (or `path` itself) that others may not pass, else None."""
    path = os.path.abspath(path)
    parts = path.split(os.sep)
    for i in range(2, len(parts) + 1):
        folder = os.sep.join(parts[:i])
        try:
            mode = os.stat(folder).st_mode
        except OSError:
            return None
        if not mode & stat.S_IXOTH:
            return folder
    return None


venv = sys.argv[1]
for what, path in (("its interpreter", os.path.realpath(os.path.join(venv, "bin", "python3"))),
                   ("the venv", os.path.join(venv, "bin", "flip"))):
    folder = closed_folder(path)
    if folder:
        print(f"make grade-deps: note: FLIP runs only as {os.stat(folder).st_uid == os.getuid() and 'you' or 'its owner'}: "
              f"{what} ({path}) is inside {folder}, which no one else may enter (mode "
              f"{stat.S_IMODE(os.stat(folder).st_mode):04o}). A grader run as another user stops with 'flip cannot be run "
              f"... Permission denied'. Make it in a checkout that user can reach, with a Python outside {folder}: "
              f"rm -rf {venv} && make grade-deps GRADE_PYTHON=/usr/bin/python3")
        break
