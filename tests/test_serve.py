"""scripts/serve.py: the server's connections send at once (TCP_NODELAY), also on a
listening socket made the way Streamlit makes it (no protocol named, proto 0); a static
file's best encodings are kept on disk and the next server serves them from there; page
scripts take turns (scripts/turns.py); a session's messages wait 1 ms between flushes, not
Streamlit's 5."""

from __future__ import annotations

import asyncio
import asyncio.base_events
import gzip
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import brotli
from streamlit import delta_generator
from streamlit.runtime import runtime, runtime_util
from streamlit.runtime.scriptrunner.script_runner import ScriptRunner

from scripts import serve

ROOT = Path(__file__).resolve().parents[1]


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


def launch(monkeypatch, tmp_path, frozen: list | None = None) -> list:
    """scripts/serve.py's main with Streamlit's own left out, every global it patches put
    back after the test, its store in ``tmp_path``, this process's objects not frozen (the
    calls go to ``frozen``); the arguments it would have handed to ``streamlit run``."""
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")
    monkeypatch.setattr(serve.gc, "freeze", lambda: (frozen if frozen is not None else []).append(1))
    monkeypatch.setattr(delta_generator, "_use_warning_has_been_displayed",
                        delta_generator._use_warning_has_been_displayed)
    monkeypatch.setattr(asyncio.base_events, "_set_nodelay", asyncio.base_events._set_nodelay)
    monkeypatch.setattr(serve.starlette_app, "create_streamlit_middleware",
                        serve.starlette_app.create_streamlit_middleware)
    monkeypatch.setattr(ScriptRunner, "_run_script", ScriptRunner._run_script)
    monkeypatch.setattr(runtime, "MESSAGE_FLUSH_INTERVAL_SECS", runtime.MESSAGE_FLUSH_INTERVAL_SECS)
    started = []
    monkeypatch.setattr(serve.cli, "main", lambda: started.append(serve.sys.argv))
    monkeypatch.setattr(serve.sys, "argv", ["serve.py", "app.py", "--server.port", "8999"])
    serve.main()
    return started


def test_the_launcher_turns_nagle_s_algorithm_off_on_every_accepted_connection(monkeypatch, tmp_path):
    assert launch(monkeypatch, tmp_path) == [["streamlit", "run", "app.py", "--server.port", "8999"]]
    assert accepted_nodelay() == 1


def test_the_launcher_warms_what_a_process_s_first_runs_would_pay(monkeypatch, tmp_path):
    """Before it serves: the app's modules and Streamlit's emoji and icon names imported,
    the store's engine made (its schema there), Streamlit's direct-execution warning taken
    as given (its check read the source of every frame of the first run's stack), and all
    that frozen for the collector."""
    frozen = []
    launch(monkeypatch, tmp_path, frozen)
    assert frozen == [1]
    assert (tmp_path / "class.db").exists()
    assert delta_generator._use_warning_has_been_displayed
    wanted = ["ui.practice", "figures.plans", "methods.progress", "solvers.kinematics",
              "mechanisms.loader", "classes.store", "exams.judged", "streamlit.emojis",
              "streamlit.material_icon_names", "solvers.__main__"]
    imported = subprocess.run(  # (a process of its own: this one has imported most already)
        [sys.executable, "-c", "import sys; from scripts import serve; serve.warm(); "
         f"print([m in sys.modules for m in {wanted!r}])"],
        cwd=ROOT, capture_output=True, text=True, timeout=120, check=True,
        env={**os.environ, "MEHANIZMI_DATABASE_URL": f"sqlite:///{tmp_path / 'fresh.db'}"})
    assert imported.stdout.strip() == str([True] * (len(wanted) - 1) + [False])  # (no command line run)


def test_a_store_not_reached_yet_does_not_stop_the_server(monkeypatch, capsys):
    monkeypatch.setattr(serve, "PACKAGES", ())
    monkeypatch.setattr(delta_generator, "_use_warning_has_been_displayed",
                        delta_generator._use_warning_has_been_displayed)

    def down(*_args):
        raise ConnectionRefusedError("no server on that socket")

    monkeypatch.setattr("classes.store.engine", down)
    monkeypatch.setattr(serve.gc, "freeze", lambda: None)
    serve.warm()
    assert "the class store is not reached yet: ConnectionRefusedError" in capsys.readouterr().err


def test_the_launcher_shortens_streamlit_s_pause_between_sending_a_session_s_messages(
        monkeypatch, tmp_path):
    """Streamlit's loop sleeps 5 ms after each flush of a session's messages (if this first
    assertion fails, Streamlit changed it upstream); the runtime's loop reads the pause from
    its module's globals, where the launcher sets it."""
    assert runtime_util.MESSAGE_FLUSH_INTERVAL_SECS == 0.005
    loop = runtime.Runtime._loop_coroutine
    assert "MESSAGE_FLUSH_INTERVAL_SECS" in loop.__code__.co_names
    assert loop.__globals__ is vars(runtime)
    launch(monkeypatch, tmp_path)
    assert runtime.MESSAGE_FLUSH_INTERVAL_SECS == serve.FLUSH < 0.005


def test_the_launcher_makes_every_script_run_take_turns(monkeypatch, tmp_path):
    """scripts/turns.py, tested on its own in tests/test_turns.py."""
    original = ScriptRunner._run_script
    launch(monkeypatch, tmp_path)
    assert ScriptRunner._run_script is not original
    assert ScriptRunner._run_script.__wrapped__ is original


SCRIPT = b"function draw(plan) { return plan.poles.map((p) => p.scale); }\n" * 400


def _get(middleware, coding: bytes) -> tuple[dict, bytes]:
    """One GET of a static script through the middleware, as a browser accepting ``coding``."""
    async def script_app(scope, receive, send):
        await send({"type": "http.response.start", "status": 200,
                    "headers": [(b"content-type", b"application/javascript"),
                                (b"etag", b"v1")]})
        await send({"type": "http.response.body", "body": SCRIPT})

    middleware.app = script_app
    sent: list[dict] = []

    async def collect(message):
        sent.append(message)

    scope = {"type": "http", "method": "GET", "path": "/static/js/index.abc123.js",
             "headers": [(b"accept-encoding", coding)]}
    asyncio.run(middleware(scope, None, collect))
    return dict(sent[0]["headers"]), sent[1]["body"]


def test_the_best_encodings_are_stored_by_content_and_a_new_server_serves_them(tmp_path):
    first = serve.PrecompressedStatic(None, store=tmp_path)
    headers, body = _get(first, b"gzip")
    assert headers[b"content-encoding"] == b"gzip" and gzip.decompress(body) == SCRIPT
    headers, body = _get(first, b"br")
    assert headers[b"content-encoding"] == b"br" and brotli.decompress(body) == SCRIPT
    for _ in range(200):  # quality 11 is written on the background thread
        if len(list(tmp_path.glob("*.br"))) == 1:
            break
        time.sleep(0.05)
    (stored_br,) = tmp_path.glob("*.br")
    (stored_gz,) = tmp_path.glob("*.gzip")
    assert brotli.decompress(stored_br.read_bytes()) == SCRIPT
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([stored_br.name, stored_gz.name])

    marked = brotli.compress(SCRIPT, quality=1)  # not what either quality here writes
    stored_br.write_bytes(marked)
    again = serve.PrecompressedStatic(None, store=tmp_path)
    assert _get(again, b"br")[1] == marked  # read from the store, not compressed anew
    assert _get(again, b"gzip")[1] == stored_gz.read_bytes()


def test_a_page_head_names_files_from_the_static_folder_its_server_serves(monkeypatch):
    """Streamlit serves /app/static/ from beside the script it runs; the head must look there
    (a floor app's server named the app's bundle before the floor had published its own)."""
    for script, static in (("bench/floor_chart_app.py", "bench/static"), ("app.py", "static")):
        monkeypatch.setattr(serve.config, "_main_script_path", str(serve.ROOT / script))
        assert serve._app_static() == serve.ROOT / static


def test_a_page_head_names_the_server_s_path_and_starts_the_charts_bundle(tmp_path):
    """scripts/page_head.py: Streamlit's front end is told the server's path (no 404 probe
    first), Plotly's basic bundle is started by the charts' own loader, under the URL the
    charts ask for (ui/plot.py), so a chart finds it already loading, and the charts' script
    is fetched as a module from the head."""
    from scripts import page_head

    assert [page_head.base_url(p) for p in ("", "/", "mehanizmi", "/a/b/")] == \
        ["/", "/", "/mehanizmi/", "/a/b/"]
    (tmp_path / "plotly-basic-9.9.9.min.js").write_text("")
    assert "modulepreload" not in page_head.head("", static=tmp_path)  # no script published
    (tmp_path / "plot-0123456789ab.js").write_text("")
    tags = page_head.head("mehanizmi", static=tmp_path)
    assert '<link rel="modulepreload" href="app/static/plot-0123456789ab.js">' in tags
    assert 'BACKEND_BASE_URL: new URL("/mehanizmi/", location.href).href' in tags
    loader = (page_head.ROOT / "ui" / "plotly_loader.js").read_text(encoding="utf-8")
    assert page_head.LOADER == loader
    assert page_head.LOADER in tags
    assert 'plotly("app/static/plotly-basic-9.9.9.min.js");' in tags
    assert "plotly(" not in page_head.head("", static=tmp_path / "none")  # no bundle published
    # the page's frame (ui/frame.css) is one style, which the server puts last in the body
    frame = (page_head.ROOT / "ui" / "frame.css").read_text(encoding="utf-8")
    assert "stCaptionContainer" in frame and page_head.FRAME == f"<style>\n{frame}</style>"
