"""scripts/serve.py: the server's connections send at once (TCP_NODELAY), also on a
listening socket made the way Streamlit makes it (no protocol named, proto 0)."""

from __future__ import annotations

import asyncio
import asyncio.base_events
import socket

from scripts import serve


def accepted_nodelay() -> int:
    """TCP_NODELAY of a connection accepted by asyncio on a proto-0 listening socket."""
    async def run() -> int:
        listener = socket.socket(family=socket.AF_INET)  # as Streamlit binds its port
        listener.bind(("127.0.0.1", 0))
        accepted: asyncio.Future = asyncio.get_running_loop().create_future()

        def connected(reader, writer):
            sock = writer.get_extra_info("socket")
            accepted.set_result(sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY))
            writer.close()

        server = await asyncio.start_server(connected, sock=listener)
        _, writer = await asyncio.open_connection(*listener.getsockname())
        value = await asyncio.wait_for(accepted, 10)
        writer.close()
        server.close()
        await server.wait_closed()
        return value

    return asyncio.run(run())


def test_without_the_launcher_such_connections_keep_nagle_s_algorithm():
    """Why scripts/serve.py exists; if this fails, Python or Streamlit fixed it upstream."""
    assert accepted_nodelay() == 0


def test_the_launcher_turns_nagle_s_algorithm_off_on_every_accepted_connection(monkeypatch):
    monkeypatch.setattr(asyncio.base_events, "_set_nodelay", asyncio.base_events._set_nodelay)
    started = []
    monkeypatch.setattr(serve.cli, "main", lambda: started.append(serve.sys.argv))
    monkeypatch.setattr(serve.sys, "argv", ["serve.py", "app.py", "--server.port", "8999"])
    serve.main()
    assert started == [["streamlit", "run", "app.py", "--server.port", "8999"]]
    assert accepted_nodelay() == 1

