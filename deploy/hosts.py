"""Several machines on this one, for ``deploy/loadtest.py --class N --hosts H``: network
namespaces made here and nowhere else — a LAN (a bridge in a namespace of its own), PostgreSQL
in one host, H app hosts (``deploy/start.sh --role app``), nginx in another (``--role
proxy``) and a client host from which the class's phones connect. Only the addresses of
these namespaces are used (10.213.77.0/24, which exists inside them alone); every namespace
is removed at the end, and with it every veth.

Needs root (``ip netns``); :func:`why_not` says why it cannot run otherwise.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import signal
import subprocess
import tempfile
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from .client import healthy

ROOT = Path(__file__).resolve().parents[1]
NET = "10.213.77."  # the LAN's addresses: .1 the database, .2… the app hosts, then proxy, client
PORT = 8080  # nginx's, on the proxy host
APP_PORT = 8601  # each app host's first process
CLONE_NEWNET = 0x40000000
AS_POSTGRES = ["runuser", "-u", "postgres", "--"]  # (PostgreSQL refuses to run as root)


def why_not() -> str | None:
    """Why namespaces cannot be made here, or None."""
    if os.getuid() != 0:
        return "network namespaces need root (ip netns)"
    if shutil.which("ip") is None or shutil.which("nginx") is None:
        return "ip (iproute2) and nginx are needed"
    if not list(Path("/usr/lib/postgresql").glob("*/bin/pg_ctl")):
        return "PostgreSQL's server is not installed"
    return None


def ip(*args: str) -> None:
    subprocess.run(["ip", *args], check=True, capture_output=True, timeout=30)


@dataclass
class Hosts:
    """The namespaces, their processes and where each host's files are."""

    prefix: str
    apps: list[str]  # the app hosts' names, "app1" …
    scratch: Path
    started: dict[str, subprocess.Popen] = field(default_factory=dict)
    killed: set[str] = field(default_factory=set)

    def ns(self, host: str) -> str:
        return f"{self.prefix}-{host}"

    def address(self, host: str) -> str:
        order = ["db", *self.apps, "proxy", "client"]
        return NET + str(order.index(host) + 1)

    @property
    def database(self) -> str:
        return f"postgresql+psycopg://postgres@{self.address('db')}:5432/postgres"

    @property
    def proxy(self) -> str:
        return f"http://{self.address('proxy')}:{PORT}"

    def host_of(self, upstream: str) -> str | None:
        """The app host an ``X-Mehanizmi-Upstream`` names (its last address: after a
        failover nginx lists the ones tried first)."""
        last = upstream.split(",")[-1].strip().rsplit(":", 1)[0]
        return next((h for h in self.apps if self.address(h) == last), None)

    def pids(self, host: str) -> list[int]:
        """Every process inside a host's namespace."""
        out = subprocess.run(["ip", "netns", "pids", self.ns(host)], capture_output=True,
                             text=True, timeout=30).stdout
        return [int(p) for p in out.split()]

    def app_pids(self) -> list[int]:
        """The app processes (their CPU is the deployment's cost) on the hosts still up."""
        return [p for h in self.apps if h not in self.killed for p in self.pids(h)
                if b"scripts/serve.py" in _cmdline(p)]

    def database_pids(self) -> list[int]:
        return self.pids("db")

    def kill(self, host: str) -> int:
        """A machine lost: every process of ``host`` killed at once (its network stays, so
        nginx's connections to it are refused, as a crashed host's would time out)."""
        self.killed.add(host)
        pids = self.pids(host)
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        return len(pids)

    def gone(self) -> str | None:
        """A host whose start script stopped, with its last words (nothing to wait for)."""
        for host, process in self.started.items():
            if process.poll() is not None:
                said = (self.scratch / host / "start.log").read_text()[-800:]
                return f"{host}'s deploy/start.sh stopped (exit {process.returncode}): {said}"
        return None

    def stop(self) -> None:
        """Everything stopped, every namespace and file removed (also after a failure)."""
        for process in self.started.values():
            if process.poll() is None:
                process.send_signal(signal.SIGTERM)
        for process in self.started.values():
            try:
                process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
        if (self.scratch / "pg" / "postmaster.pid").exists():  # (its shared memory freed)
            subprocess.run([*AS_POSTGRES, str(pg_bin() / "pg_ctl"), "-D", str(self.scratch / "pg"),
                            "-m", "fast", "-w", "stop"], capture_output=True, timeout=60)
        for host in ["db", *self.apps, "proxy", "client"]:
            if Path(f"/run/netns/{self.ns(host)}").exists():
                self.kill(host)  # (whatever is left)
        for host in ["db", *self.apps, "proxy", "client", "lan"]:
            subprocess.run(["ip", "netns", "del", self.ns(host)], capture_output=True, timeout=30)
        shutil.rmtree(self.scratch, ignore_errors=True)


def _cmdline(pid: int) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


def make(apps: int) -> Hosts:
    """The LAN and its hosts, with nothing started yet."""
    hosts = Hosts(f"mz{os.getpid() % 100000}", [f"app{i + 1}" for i in range(apps)],
                  Path(tempfile.mkdtemp(prefix="mz-hosts-")))
    hosts.scratch.chmod(0o711)  # (PostgreSQL runs as its own user, inside it)
    try:
        lan = hosts.ns("lan")
        ip("netns", "add", lan)
        ip("-n", lan, "link", "add", "br0", "type", "bridge")
        ip("-n", lan, "link", "set", "br0", "up")
        for i, host in enumerate(["db", *hosts.apps, "proxy", "client"]):
            ns = hosts.ns(host)
            ip("netns", "add", ns)
            ip("link", "add", "eth0", "netns", ns, "type", "veth",
               "peer", "name", f"port{i}", "netns", lan)
            ip("-n", ns, "addr", "add", hosts.address(host) + "/24", "dev", "eth0")
            for link in ("lo", "eth0"):
                ip("-n", ns, "link", "set", link, "up")
            ip("-n", lan, "link", "set", f"port{i}", "master", "br0", "up")
    except BaseException:
        hosts.stop()
        raise
    return hosts


def _in(hosts: Hosts, host: str, command: list[str], env: dict, log: Path) -> subprocess.Popen:
    return subprocess.Popen(["ip", "netns", "exec", hosts.ns(host), *command], cwd=ROOT,
                            env=env, stdout=log.open("w"), stderr=subprocess.STDOUT,
                            start_new_session=True)


def start(apps: int = 2, app: str = "asgi.py", seconds: float = 180) -> Hosts:
    """PostgreSQL, ``apps`` app hosts (one process each: the machine has two cores) and the
    proxy, each in its namespace; returns once nginx answers through every host."""
    hosts = make(apps)
    try:
        _database(hosts)
        shared = hosts.scratch / "shared"  # what every app host is given: one secret, one key
        shared.mkdir()
        base = {k: v for k, v in os.environ.items() if not k.startswith("MEHANIZMI_")}
        common = {**base, "MEHANIZMI_COOKIE_SECRET": os.urandom(32).hex(),
                  "MEHANIZMI_LTI_KEY": str(shared / "tool-key.pem"),
                  "MEHANIZMI_BASE_URL": hosts.proxy}
        subprocess.run([str(ROOT / ".venv/bin/python"), "-m", "solvers", "lti", "tool",
                        "--base-url", hosts.proxy], cwd=ROOT, env=common, check=True,
                       capture_output=True, timeout=120)  # (makes the key, as a first host does)
        for host in hosts.apps:
            own = hosts.scratch / host
            own.mkdir()
            env = {**common, "HOST": hosts.address(host), "PROCESSES": "1", "APP": app,
                   "FIRST_APP_PORT": str(APP_PORT), "MEHANIZMI_DATA": str(own / "data"),
                   "MEHANIZMI_LOGS": str(own / "logs")}
            hosts.started[host] = _in(hosts, host, ["bash", "deploy/start.sh", "--role", "app",
                                                    "--database", hosts.database], env, own / "start.log")
        own = hosts.scratch / "proxy"
        own.mkdir()
        upstreams = [f"{hosts.address(h)}:{APP_PORT}" for h in hosts.apps]
        env = {**base, "HOST": hosts.address("proxy"), "PORT": str(PORT),
               "MEHANIZMI_LOGS": str(own / "logs")}
        hosts.started["proxy"] = _in(hosts, "proxy", ["bash", "deploy/start.sh", "--role", "proxy",
                                                      "--upstream", *upstreams], env, own / "start.log")
        with inside(hosts, "client"):
            for host in hosts.apps:
                healthy(f"http://{hosts.address(host)}:{APP_PORT}", seconds, hosts.gone)
            healthy(hosts.proxy, seconds, hosts.gone)
    except BaseException:
        hosts.stop()
        raise
    return hosts


def pg_bin() -> Path:
    return sorted(Path("/usr/lib/postgresql").glob("*/bin"))[-1]


def _database(hosts: Hosts) -> None:
    """PostgreSQL on the database host, open to the LAN alone (trust: the LAN is this test's)."""
    bin_dir = pg_bin()
    data = hosts.scratch / "pg"
    data.mkdir()
    shutil.chown(data, "postgres")
    subprocess.run([*AS_POSTGRES, str(bin_dir / "initdb"), "-D", str(data), "-A", "trust",
                    "-U", "postgres"], check=True, capture_output=True, timeout=120)
    with (data / "pg_hba.conf").open("a") as hba:
        hba.write(f"host all all {NET}0/24 trust\n")
    subprocess.run(["ip", "netns", "exec", hosts.ns("db"), *AS_POSTGRES, str(bin_dir / "pg_ctl"),
                    "-D", str(data), "-l", str(data / "server.log"), "-w", "-o",
                    f"-k {data} -c listen_addresses={hosts.address('db')} -c max_connections=200",
                    "start"], check=True, capture_output=True, timeout=120)


@contextmanager
def inside(hosts: Hosts, host: str):
    """This thread in ``host``'s network (sockets made meanwhile stay there): the class's
    phones and the store's connections are the client host's."""
    libc = ctypes.CDLL(None, use_errno=True)
    home = os.open("/proc/thread-self/ns/net", os.O_RDONLY)
    there = os.open(f"/run/netns/{hosts.ns(host)}", os.O_RDONLY)
    try:
        if libc.setns(there, CLONE_NEWNET) != 0:
            raise OSError(ctypes.get_errno(), f"setns into {hosts.ns(host)}")
        yield
    finally:
        libc.setns(home, CLONE_NEWNET)
        os.close(home)
        os.close(there)
