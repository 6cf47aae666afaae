"""Serves FOLDER over HTTP on 127.0.0.1 at a free port, for the OME-Zarr URL tests.

Usage: serve_folder.py FOLDER LOG. Prints "port N" once it listens; appends the path of each
GET to LOG (the tests count what a load requested). A path under /status500/ answers HTTP 500
(a failing server), anything else is Python's http.server serving FOLDER.
"""
import functools
import http.server
import sys

folder, log = sys.argv[1], sys.argv[2]


class Handler(http.server.SimpleHTTPRequestHandler):
    def do_GET(self):
        with open(log, "a", encoding="utf-8") as f:
            f.write(self.path + "\n")
        if self.path.startswith("/status500/"):
            self.send_error(500, "test: a failing server")
            return
        super().do_GET()

    def log_message(self, format, *args):  # the log above is the one the tests read
        pass


server = http.server.ThreadingHTTPServer(
    ("127.0.0.1", 0), functools.partial(Handler, directory=folder))
print("port", server.server_address[1], flush=True)
server.serve_forever()
