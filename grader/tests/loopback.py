"""A server on 127.0.0.1 that records every connection: the hostile suites' network attack connects to
it, and a sandbox that contains the attack leaves its list empty."""
import socket
import threading


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
