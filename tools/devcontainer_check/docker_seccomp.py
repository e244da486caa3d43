#!/usr/bin/env python3
"""Runs a command under the part of Docker's default seccomp profile that concerns the grader's sandbox:
for a process without CAP_SYS_ADMIN, Docker's profile refuses unshare, setns, mount, umount2 and
pivot_root, clone with any namespace flag (EPERM), and clone3 (ENOSYS, so that the C library falls back
to clone). make devcontainer-check runs `make check` under it to show what a student sees in a container
started with Docker's defaults. Needs Debian's python3-seccomp (libseccomp's binding).

usage: docker_seccomp.py COMMAND [ARGS...]"""
import errno
import os
import sys

import seccomp

# CLONE_NEWNS, NEWCGROUP, NEWUTS, NEWIPC, NEWUSER, NEWPID, NEWNET: Docker's mask 0x7E020000.
NAMESPACE_FLAGS = (0x00020000, 0x02000000, 0x04000000, 0x08000000, 0x10000000, 0x20000000, 0x40000000)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    rules = seccomp.SyscallFilter(defaction=seccomp.ALLOW)
    for call in ("unshare", "setns", "mount", "umount2", "pivot_root"):
        rules.add_rule(seccomp.ERRNO(errno.EPERM), call)
    for flag in NAMESPACE_FLAGS:
        rules.add_rule(seccomp.ERRNO(errno.EPERM), "clone", seccomp.Arg(0, seccomp.MASKED_EQ, flag, flag))
    rules.add_rule(seccomp.ERRNO(errno.ENOSYS), "clone3")
    rules.load()  # sets no_new_privs first, as an unprivileged process must
    try:
        os.execvp(sys.argv[1], sys.argv[1:])
    except OSError as error:
        print(f"docker_seccomp: {sys.argv[1]}: {error.strerror}", file=sys.stderr)
        return 127


if __name__ == "__main__":
    sys.exit(main())
