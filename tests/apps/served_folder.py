"""A folder served over HTTP on a free port of 127.0.0.1, for the pages a test opens from a server,
by a handler that may play a server's part (slow, cut off, without byte ranges)."""
import contextlib
import functools
import http.server
import threading


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    """Python's own server (no byte ranges), without its log of every request on stderr."""

    def log_message(self, *args):
        pass


@contextlib.contextmanager
def served(folder, handler=QuietHandler):
    """Yields the origin, "http://127.0.0.1:PORT/", while `folder` is served by `handler`."""
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(handler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
