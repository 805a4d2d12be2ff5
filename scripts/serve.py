"""Serve the app: ``streamlit run`` with Nagle's algorithm off on the server's connections.

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


def _set_nodelay(sock: socket.socket) -> None:
    if sock.family in (socket.AF_INET, socket.AF_INET6) and sock.type == socket.SOCK_STREAM:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


def main() -> None:
    asyncio.base_events._set_nodelay = _set_nodelay  # called for every accepted connection
    sys.argv = ["streamlit", "run", *sys.argv[1:]]
    cli.main()


if __name__ == "__main__":
    main()
