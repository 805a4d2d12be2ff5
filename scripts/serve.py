"""Serve the app: ``streamlit run`` with Nagle's algorithm off on the server's connections,
static files gzipped once for a browser that accepts it, and the sessions' page scripts run
one at a time (scripts/turns.py).

The flush pause: Streamlit's loop sends a session's queued messages, then sleeps 5 ms
(``MESSAGE_FLUSH_INTERVAL_SECS``) before it looks again. A page whose run takes longer than
that had its later messages wait for the next look: the plans page's φ₂ rerun ran its
script in 7 ms and its last message left at 14 ms (a timeline of the server's sends), a
one-slider page's run fits in the first look. At 1 ms (``FLUSH``) the pages' reruns went
13–14 → 9–10 ms (bench/pages.py) and 30 sessions at once from p50 18 / p95 49 to 12 / 34 ms
(deploy/loadtest.py); the pause still gathers a run's messages under a class's load.

Nagle: Streamlit (1.67) creates its listening socket without naming TCP as the protocol, and
asyncio sets TCP_NODELAY only on sockets that name it. With Nagle's algorithm on, every
message a rerun sends after the first waits for the browser's delayed ACK, 40 ms on Linux: a
one-slider page took 46 ms a rerun, of which 4 ms was work (bench/pages.py measures it).

Compression: Streamlit serves its own scripts (``/static/…``, content-hashed) and ours
(``/app/static/…``: Plotly's bundles, named by version) uncompressed: compressing at the
origin on every request cost it CPU under load, so it leaves compression to a proxy. On a
mobile link those 3.6–5.1 MB were most of a first visit's five seconds. Here each file is
compressed once (Brotli, or gzip for a client without it), the first time it is asked for,
and kept: every later request is served from memory. The best-quality encodings are also
kept on disk by content (``.cache/compressed/``), so a server that starts again (a deploy,
each browser test's server) serves them at once instead of compressing the same megabytes
anew. Our bundles and the charts' script get the year-long immutable lifetime Streamlit
gives its own (their names carry a version or a hash of their content).
Streamlit's icon font is served cut to the icons the app can show (scripts/icon_font.py),
and a page's HTML gets the tags of scripts/page_head.py (Plotly started from the head, the
server's address given).

    .venv/bin/python scripts/serve.py app.py [streamlit run's options]
"""

from __future__ import annotations

import asyncio.base_events
import gc
import gzip
import hashlib
import importlib
import os
import pkgutil
import queue
import socket
import sys
import threading
from pathlib import Path

import brotli
from streamlit import config, delta_generator, file_util
from streamlit.runtime import runtime
from streamlit.web import cli
from streamlit.web.server.starlette import starlette_app

sys.path.insert(0, str(Path(__file__).resolve().parent))
import page_head  # noqa: E402
import turns  # noqa: E402
from icon_font import FONT, ROOT, STATIC, cut_path  # noqa: E402

COMPRESSIBLE = (b"text/", b"application/javascript", b"application/json", b"image/svg+xml")
SMALLEST = 1024  # below this the gzip header is not worth it
PREFIXES = ("/static/", "/app/static/")
YEAR = b"public, immutable, max-age=31536000"
NAMED = ("/app/static/plotly-", "/app/static/plot-")  # Plotly's bundles, ui/plot.py's script
STORE = ROOT / ".cache" / "compressed"  # best encodings by content: <sha256>.<coding>
FLUSH = 0.001  # s: Streamlit's pause between sending a session's queued messages (5 ms)


def _coding(scope) -> bytes | None:
    """The best encoding the client accepts: Brotli (about a tenth smaller than gzip on
    these scripts, a fifth at its best quality), else gzip, else none."""
    accepted = b",".join(value.lower() for name, value in scope.get("headers", ())
                         if name == b"accept-encoding")
    return b"br" if b"br" in accepted else b"gzip" if b"gzip" in accepted else None


class PrecompressedStatic:
    """ASGI middleware: a GET of a static file by a client that accepts Brotli or gzip gets
    the file compressed (once per file, version and encoding, then kept); anything else
    passes. Brotli is written at quality 5 at once (35 ms a megabyte) and at quality 11 in
    the background (3 s a megabyte, off the event loop: brotli lets go of the GIL), which
    every later visitor gets; that and gzip's best are stored on disk by content (``store``)
    and read from there by the next server."""

    def __init__(self, app, cache_limit: int = 128, store: Path = STORE):
        self.app = app
        self.cache: dict[tuple, bytes] = {}
        self.cache_limit = cache_limit
        self.store = store
        self.best: queue.SimpleQueue = queue.SimpleQueue()  # (key, data, file) for quality 11
        # a daemon: a server stopping does not wait for a file still being compressed
        threading.Thread(target=self._write_best, name="brotli", daemon=True).start()

    def _write_best(self) -> None:
        while True:
            key, data, file = self.best.get()
            best = brotli.compress(data, quality=11)
            _keep(file, best)
            if key in self.cache:  # (not if it was dropped from a full cache meanwhile)
                self.cache[key] = best

    async def __call__(self, scope, receive, send):
        path = scope.get("path", "")
        if scope["type"] == "http" and FONT.match(path):
            await self._icon_font(path, scope, receive, send)
            return
        if scope["type"] == "http" and scope.get("method") == "GET" and _is_page(path):
            await self._with_head(scope, receive, send)
            return
        coding = _coding(scope)
        if (scope["type"] != "http" or scope.get("method") != "GET"
                or not path.startswith(PREFIXES) or coding is None):
            await self.app(scope, receive, send)
            return
        start, data = await self._whole(scope, receive)
        headers = [(k.lower(), v) for k, v in start.get("headers", [])]
        named = dict(headers)
        if (start.get("status") != 200 or len(data) < SMALLEST or named.get(b"content-encoding")
                or not named.get(b"content-type", b"").startswith(COMPRESSIBLE)):
            await send(start)
            await send({"type": "http.response.body", "body": data})
            return
        key = (path, len(data), named.get(b"etag"), named.get(b"last-modified"), coding)
        packed = self.cache.get(key)
        if packed is None:
            packed = self._compress(key, data, coding)
        kept = [(k, v) for k, v in headers if k != b"vary"]
        if path.startswith(NAMED):  # named by version or content: never changes
            kept = [(k, v) for k, v in kept if k != b"cache-control"] + [(b"cache-control", YEAR)]
        kept += [(b"content-encoding", coding), (b"vary", b"Accept-Encoding")]
        await send(_sized({**start, "headers": kept}, packed))
        await send({"type": "http.response.body", "body": packed})

    async def _whole(self, scope, receive) -> tuple[dict, bytes]:
        """Streamlit's answer held back: its start message and its whole body."""
        start: dict = {}
        body: list[bytes] = []

        async def capture(message):
            if message["type"] == "http.response.start":
                start.update(message)
            elif message["type"] == "http.response.body":
                body.append(message.get("body", b""))

        await self.app(scope, receive, capture)
        return start, b"".join(body)

    def _compress(self, key: tuple, data: bytes, coding: bytes) -> bytes:
        if len(self.cache) >= self.cache_limit:
            self.cache.pop(next(iter(self.cache)))
        file = self.store / f"{hashlib.sha256(data).hexdigest()}.{coding.decode()}"
        if file.exists():
            packed = self.cache[key] = file.read_bytes()
        elif coding == b"gzip":
            packed = self.cache[key] = gzip.compress(data, compresslevel=9, mtime=0)
            _keep(file, packed)
        else:
            packed = self.cache[key] = brotli.compress(data, quality=5)
            self.best.put((key, data, file))
        return packed

    async def _with_head(self, scope, receive, send) -> None:
        """A page's HTML with scripts/page_head.py's tags in its head, and its frame's style
        closing its body."""
        start, data = await self._whole(scope, receive)
        named = {k.lower(): v for k, v in start.get("headers", [])}
        if (start.get("status") == 200 and b"</head>" in data
                and named.get(b"content-type", b"").startswith(b"text/html")
                and not named.get(b"content-encoding")):
            tags = page_head.head(config.get_option("server.baseUrlPath"), _app_static())
            data = data.replace(b"</head>", tags.encode() + b"</head>", 1)
            data = data.replace(b"</body>", page_head.FRAME.encode() + b"</body>", 1)
            start = _sized(start, data)
        await send(start)
        await send({"type": "http.response.body", "body": data})

    async def _icon_font(self, path: str, scope, receive, send) -> None:
        """Streamlit's icon font as cut by scripts/icon_font.py (a tenth of its bytes), when
        the cut is there; Streamlit's own answer otherwise."""
        cut = cut_path(STATIC / "media" / path.rsplit("/", 1)[1])
        if not cut.exists():
            await self.app(scope, receive, send)
            return
        start, data = await self._whole(scope, receive)
        if start.get("status") == 200:
            data = self.cache.get((path, "cut"))
            if data is None:
                data = self.cache[(path, "cut")] = cut.read_bytes()
            start = _sized(start, data)
        await send(start)
        await send({"type": "http.response.body", "body": data})


def _keep(file: Path, packed: bytes) -> None:
    """Store an encoding whole or not at all (written aside, then renamed): two servers may
    write the same file, and one stopping halfway must not leave half a file."""
    file.parent.mkdir(parents=True, exist_ok=True)
    aside = file.with_name(f"{file.name}.{os.getpid()}.{threading.get_ident()}")
    aside.write_bytes(packed)
    aside.replace(file)


def _sized(start: dict, body: bytes) -> dict:
    """A response's start message whose Content-Length is ``body``'s."""
    headers = [(k, v) for k, v in start.get("headers", []) if k.lower() != b"content-length"]
    return {**start, "headers": [*headers, (b"content-length", str(len(body)).encode())]}


def _app_static() -> Path:
    """The folder this server serves as ``/app/static/``: ``static/`` beside the script it runs
    (the app's, or a benchmark's floor app's). The page head names only files found there: it
    named the app's Plotly bundle on the floor's server before the floor had published its
    own, and the 404 left the floor's first visit without a chart."""
    return Path(file_util.get_app_static_dir(config._main_script_path))


def _is_page(path: str) -> bool:
    """A page of the app (``/``, ``/kinetostatics``): its HTML, not a file or the API."""
    return "." not in path and not path.startswith(("/_stcore", "/static", "/app", "/component"))


def _set_nodelay(sock: socket.socket) -> None:
    if sock.family in (socket.AF_INET, socket.AF_INET6) and sock.type == socket.SOCK_STREAM:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


def _with_precompressed():
    """Streamlit's middleware, and the static files gzipped once innermost (Streamlit's own
    gzip layer passes static paths through untouched)."""
    from starlette.middleware import Middleware

    return [*_streamlit_middleware(), Middleware(PrecompressedStatic)]


_streamlit_middleware = starlette_app.create_streamlit_middleware


def warm() -> None:
    """Before the first session, what a process's first runs would otherwise pay while a
    class waits behind them (a class opens its pages at once, and each process queues their
    runs: its first opening took 500 ms, the floor's 250, and every opening in the queue
    waited that long too; ``kill -9`` and a restart send a whole class back at once):

    - every module of the app's packages, imported: the first sessions arrive at once, each
      page script in a thread of its own, and two threads importing the same modules in
      opposite orders met Python's import-deadlock escape, which hands one of them a
      half-made module ("cannot import name 'boundary' from 'ui.boundary'", seen by the
      class load test's lecturer);
    - Streamlit's emoji and icon names, which it imports the first time a page's icon is
      checked (50 ms, most of it compiling one regular expression);
    - the class store's engine: its driver imported and its schema checked (140 ms with
      PostgreSQL). A store that does not answer yet is left for the first page that asks
      (it says so there);
    - Streamlit's warning for a script run without ``streamlit run``, marked as given: this
      is ``streamlit run``, and its one check (``env_util.is_repl``) walked every frame of
      the first run's stack and read their source files, 100 ms.

    What that made lives as long as the process, and is then frozen (``gc.freeze``): the
    collector's full collections no longer walk its 190,000 objects. Each of them had
    stopped every session for 85–135 ms (under a class's load, one about every 40
    openings)."""
    sys.path.insert(0, str(ROOT))
    for name in PACKAGES:
        package = importlib.import_module(name)
        for module in pkgutil.iter_modules(package.__path__):
            if module.name != "__main__":  # (a package's command line: not run here)
                importlib.import_module(f"{name}.{module.name}")
    delta_generator._use_warning_has_been_displayed = True
    importlib.import_module("streamlit.emojis")
    importlib.import_module("streamlit.material_icon_names")
    from classes import store

    try:
        store.engine()
    except Exception as exc:  # noqa: BLE001 (any driver's error: the page says it later)
        print(f"the class store is not reached yet: {type(exc).__name__}", file=sys.stderr)
    gc.collect()
    gc.freeze()


PACKAGES = ("ui", "figures", "methods", "solvers", "mechanisms", "classes", "exams")


def main() -> None:
    warm()
    asyncio.base_events._set_nodelay = _set_nodelay  # called for every accepted connection
    runtime.MESSAGE_FLUSH_INTERVAL_SECS = FLUSH  # read by the runtime's loop at each pause
    starlette_app.create_streamlit_middleware = _with_precompressed
    turns.install()  # one page script at a time (scripts/turns.py)
    sys.argv = ["streamlit", "run", *sys.argv[1:]]
    cli.main()


if __name__ == "__main__":
    main()
