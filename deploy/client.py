"""A browser tab in Python: Streamlit's own WebSocket protocol (the protobuf messages the
web client sends and receives), for the load test and the page benchmark."""

from __future__ import annotations

import asyncio
import os
import subprocess
import sys
import time
import urllib.request
from dataclasses import dataclass, field
from pathlib import Path

import websockets
from streamlit.proto.BackMsg_pb2 import BackMsg
from streamlit.proto.ForwardMsg_pb2 import ForwardMsg

ROOT = Path(__file__).resolve().parents[1]


@dataclass
class Report:
    times: list[float] = field(default_factory=list)  # reruns: a control sent → script finished
    opening: list[float] = field(default_factory=list)  # a page opened → its first run finished
    by_page: dict[str, list[float]] = field(default_factory=dict)
    errors: list[str] = field(default_factory=list)
    wrong: list[str] = field(default_factory=list)
    memory: list[float] = field(default_factory=list)  # the server's, MB, when watched


class Session:
    """One browser tab: a WebSocket, the page's widgets as the server last drew them."""

    def __init__(self, url: str, page: str, link: str, report: Report):
        self.url, self.page, self.link, self.report = url, page, link, report
        self.widgets: dict[str, tuple[str, str]] = {}  # key → (widget id, "slider" | "number")
        self.fragments: dict[str, str] = {}  # widget id → the fragment that drew it, if any
        self.metrics: dict[str, str] = {}
        self.figure_bytes = 0  # of the last run
        self.charts = 0  # the charts it drew
        self.script_bytes = 0  # the charts' script sent with them (ui/plot.py)
        self.written = 0  # downloads whose file the run wrote (not deferred to a click)
        self.drawn: set[str] = set()  # the widgets the last run drew (a fragment's: its own)
        self.kinds: set[str] = set()  # the kinds of element it drew ("dataframe", "slider", …)
        self.whole = True  # the last run was the page's, not a fragment's
        self.page_hash = ""
        self.opened = False  # the page's first run has finished
        self.buttons: dict[str, str] = {}  # a button's key (a form's: "submit") → its id
        self.alerts: list[tuple[str, str]] = []  # ("success" | "warning" | "error" | "info", text)
        self.texts: list[str] = []  # the markdown the last run wrote
        self.every: tuple[float, str] | None = None  # a fragment's timer: (seconds, its id)

    async def run(self, ws, states=(), fragment: str = "") -> None:
        """One run of the page (or of ``fragment``, as its timer asks): ``states`` are the
        widgets changed, (id, value); True presses a button."""
        msg = BackMsg()
        msg.rerun_script.query_string = f"lang=en&{self.link}"
        msg.rerun_script.page_name = self.page
        msg.rerun_script.page_script_hash = self.page_hash
        msg.rerun_script.fragment_id = fragment
        for widget_id, value in states:  # (as a browser does: a fragment's widget reruns it)
            msg.rerun_script.fragment_id = self.fragments.get(widget_id, "")
            state = msg.rerun_script.widget_states.widgets.add()
            state.id = widget_id
            if value is True:
                state.trigger_value = True
            elif self.widgets.get(key_of(widget_id), ("", "slider"))[1] == "number":
                state.string_value = repr(float(value))  # typed (ui/numbers.py), lang=en
            else:
                state.double_array_value.data.append(value)
        start = time.perf_counter()
        await ws.send(msg.SerializeToString())
        self.metrics, self.figure_bytes, self.drawn, self.kinds = {}, 0, set(), set()
        self.charts = self.script_bytes = self.written = 0
        self.alerts, self.texts = [], []
        while True:
            fm = ForwardMsg()
            fm.ParseFromString(await ws.recv())
            kind = fm.WhichOneof("type")
            if kind == "navigation":
                self.page_hash = fm.navigation.page_script_hash
            elif kind == "auto_rerun":
                self.every = (fm.auto_rerun.interval, fm.auto_rerun.fragment_id)
            elif kind == "delta" and fm.delta.WhichOneof("type") == "new_element":
                self._element(fm.delta.new_element, fm.delta.fragment_id)
            elif kind == "script_finished":
                if fm.script_finished in (ForwardMsg.FINISHED_SUCCESSFULLY,
                                          ForwardMsg.FINISHED_FRAGMENT_RUN_SUCCESSFULLY):
                    self.whole = fm.script_finished == ForwardMsg.FINISHED_SUCCESSFULLY
                    took = time.perf_counter() - start
                    if not self.opened:
                        self.opened = True
                        self.report.opening.append(took)
                        return
                    self.report.times.append(took)
                    self.report.by_page.setdefault(self.page, []).append(took)
                    return

    def _element(self, element, fragment: str) -> None:
        which = element.WhichOneof("type")
        self.kinds.add(which)
        if which in ("slider", "text_input"):  # a number is typed as text (ui/numbers.py)
            widget_id = getattr(element, which).id
            key = key_of(widget_id)
            self.widgets[key] = (widget_id, "slider" if which == "slider" else "number")
            self.fragments[widget_id] = fragment
            self.drawn.add(key)
        elif which == "button":
            key = "submit" if element.button.is_form_submitter else key_of(element.button.id)
            self.buttons[key] = element.button.id
            self.fragments[element.button.id] = fragment
        elif which == "markdown":
            self.texts.append(element.markdown.body)
        elif which == "alert":
            self.alerts.append((ALERTS.get(element.alert.format, "info"), element.alert.body))
        elif which == "download_button" and element.download_button.url:
            self.written += 1
        elif which == "exception":
            self.report.errors.append(f"{self.page}: {element.exception.message[:200]}")
        elif which == "metric":
            self.metrics[element.metric.label] = element.metric.body
        elif which == "bidi_component" and element.bidi_component.component_name == "mehanizmi_plot":
            self.figure_bytes += len(element.bidi_component.bytes)
            self.script_bytes += len(element.bidi_component.js_content)
            self.charts += 1


ALERTS = {1: "error", 2: "warning", 3: "info", 4: "success"}  # streamlit.proto Alert.Format


def key_of(widget_id: str) -> str:
    """A widget's own key from its id (``$$ID-<hash>-<key>``; a key may hold "-")."""
    return widget_id.split("-", 2)[-1]


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[int(q * (len(ordered) - 1))]


def memory_mb(pid: int) -> float:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(port: int, script: Path = ROOT / "asgi.py", log=subprocess.DEVNULL,
                 env: dict[str, str] | None = None) -> subprocess.Popen:
    """The app served on 127.0.0.1:``port`` as scripts/start.sh serves it; its output to
    ``log`` (an open file, or discarded); ``env`` added to this process's environment."""
    return subprocess.Popen(
        [sys.executable, str(ROOT / "scripts" / "serve.py"), str(script), "--server.port", str(port),
         "--server.address", "127.0.0.1", "--server.headless", "true",
         "--browser.gatherUsageStats", "false"],
        cwd=ROOT, stdout=log, stderr=subprocess.STDOUT, env={**os.environ, **(env or {})})


async def wait_ready(url: str, seconds: float = 60) -> None:
    deadline = time.monotonic() + seconds
    while True:
        try:
            async with websockets.connect(url, subprotocols=["streamlit"], open_timeout=5):
                return
        except OSError:
            if time.monotonic() > deadline:
                raise
            await asyncio.sleep(0.5)


def healthy(address: str, seconds: float = 90, gone=lambda: None) -> None:
    """Wait until ``address`` answers Streamlit's health check; ``gone()`` names a reason to
    stop waiting at once (a start script that ended), else None."""
    deadline = time.monotonic() + seconds
    while True:
        try:
            urllib.request.urlopen(f"{address}/_stcore/health", timeout=2)
            return
        except OSError:
            why = gone()
            if why or time.monotonic() > deadline:
                raise RuntimeError(f"{address} did not answer: {why or f'not within {seconds:.0f} s'}")
            time.sleep(0.5)
