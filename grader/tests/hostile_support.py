"""Helpers of the grader's sandboxed suites (hostile/hostile.py with hostile/tga_attacks.py, and
tga/tga_loaders.py): the skip they report to ctest, the check for a checkout the uid fallback refuses,
and a server on 127.0.0.1 that records every connection (the network attacks connect to it; a sandbox
that contains them leaves it empty)."""
import os
import socket
import stat
import sys
import threading


def skip(text):
    print("SKIP: " + text)
    sys.exit(77)


def closed_folder(path):
    """The nearest folder at or above PATH that other users may not enter (mode without o+x), or None."""
    parts = os.path.realpath(path).split(os.sep)
    folders = [os.sep.join(parts[:i]) or os.sep for i in range(len(parts), 0, -1)]
    return next((f for f in folders if os.path.isdir(f) and not os.stat(f).st_mode & stat.S_IXOTH), None)


class Listener:
    def __init__(self):
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(8)
        self.port = self.server.getsockname()[1]
        self.connections = []  # the first bytes of each connection received
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.server.accept()
            except OSError:
                return
            self.connections.append(conn.recv(100))
            conn.close()

    def close(self):
        self.server.close()
