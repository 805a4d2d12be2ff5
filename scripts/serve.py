"""Serve the app: ``streamlit run`` with Nagle's algorithm off on the server's connections,
and static files gzipped once for a browser that accepts it (scripts/precompressed.py).

Streamlit (1.67) creates its listening socket without naming TCP as the protocol, and asyncio
sets TCP_NODELAY only on sockets that name it. With Nagle's algorithm on, every message a
rerun sends after the first waits for the browser's delayed ACK, 40 ms on Linux: a
one-slider page took 46 ms a rerun, of which 4 ms was work (bench/pages.py measures it).

    .venv/bin/python scripts/serve.py app.py [streamlit run's options]
"""

from __future__ import annotations

import asyncio.base_events
import socket
import sys

from streamlit.web import cli
from streamlit.web.server.starlette import starlette_app

from precompressed import PrecompressedStatic


def _set_nodelay(sock: socket.socket) -> None:
    if sock.family in (socket.AF_INET, socket.AF_INET6) and sock.type == socket.SOCK_STREAM:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


def _with_precompressed():
    """Streamlit's middleware, and the static files gzipped once innermost (Streamlit's own
    gzip layer passes static paths through untouched)."""
    from starlette.middleware import Middleware

    return [*_streamlit_middleware(), Middleware(PrecompressedStatic)]


_streamlit_middleware = starlette_app.create_streamlit_middleware


def main() -> None:
    asyncio.base_events._set_nodelay = _set_nodelay  # called for every accepted connection
    starlette_app.create_streamlit_middleware = _with_precompressed
    sys.argv = ["streamlit", "run", *sys.argv[1:]]
    cli.main()


if __name__ == "__main__":
    main()
