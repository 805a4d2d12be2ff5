"""The class-sized setup: the load test's own client and the proxy configuration."""

from __future__ import annotations

import re
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from deploy.loadtest import main

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.server
def test_a_short_load_test_runs_clean(capsys):
    """Six sessions, one per page, for a few seconds against a cold server of its own (no
    warming: the pages' first runs are part of the load): no error, no answer from another
    session, every page rerun, and the six openings told apart from the reruns."""
    assert main(["--sessions", "6", "--seconds", "6", "--warm", "0"]) == 0
    out = capsys.readouterr().out
    assert "errors: 0, wrong answers: 0" in out
    assert "pages opened: 6, first run: p50" in out and "all runs together: p50" in out
    for page in ("kinetostatics", "trajectories", "velocity_plans", "assur_groups",
                 "planetary_gears", "rotor_balancing"):
        assert page in out


def test_the_load_test_refuses_anything_but_loopback():
    with pytest.raises(SystemExit):
        main(["--url", "http://example.org:8080"])


@pytest.mark.skipif(shutil.which("nginx") is None, reason="nginx is installed by deploy/start.sh")
def test_the_proxy_configuration_is_valid_nginx(tmp_path):
    servers = "        server 127.0.0.1:8601;\n        server 127.0.0.1:8602;\n"
    text = (ROOT / "deploy" / "nginx.conf.in").read_text()
    for key, value in {"@RUN@": str(tmp_path), "@PORT@": "18080", "@HOST@": "127.0.0.1",
                       "@SERVERS@": servers}.items():
        text = text.replace(key, value)
    for sub in ("body", "proxy", "fastcgi", "uwsgi", "scgi"):
        (tmp_path / sub).mkdir()
    conf = tmp_path / "nginx.conf"
    conf.write_text(text)
    result = subprocess.run(["nginx", "-t", "-e", "stderr", "-p", str(tmp_path), "-c", str(conf)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "hash $route consistent" in text and "Upgrade $http_upgrade" in text


def test_a_piped_log_is_rotated_at_its_cap_private_and_without_keys(tmp_path):
    """deploy/logpipe.py: every line kept (the newest in the file, older in FILE.1 …), no
    file over the cap, at most ``keep`` old ones, mode 600, and each key= and student=
    value written as "…" (in a query, encoded, or in a referrer)."""
    log = tmp_path / "app.log"
    lines = [f"{n:05d} GET /class?class=ABC123&key=s3cret{n}&student=tok{n} referrer: "
             f"http://x/velocity_plans?student%3Dtok{n}" for n in range(2000)]
    done = subprocess.run([sys.executable, str(ROOT / "deploy" / "logpipe.py"), str(log),
                           "--bytes", "20000", "--keep", "3"], input="\n".join(lines) + "\n",
                          text=True, capture_output=True)
    assert done.returncode == 0, done.stderr
    files = sorted(tmp_path.iterdir())
    assert [f.name for f in files] == ["app.log", "app.log.1", "app.log.2", "app.log.3"]
    assert all(f.stat().st_size <= 20000 and stat.S_IMODE(f.stat().st_mode) == 0o600 for f in files)
    text = "".join(f.read_text() for f in files)
    assert "s3cret" not in text and "tok" not in text and "key=…" in text
    assert f"{1999:05d} GET /class?class=ABC123&key=…&student=…" in log.read_text()


def test_every_variable_the_deploy_scripts_read_is_documented():
    """docs/deploy.md's table names each variable deploy/start.sh and deploy/cli.sh read
    (``FIRST_APP_PORT`` lived in the script alone)."""
    read = set()
    for script in ("start.sh", "cli.sh"):
        read |= set(re.findall(r"\$\{([A-Z][A-Z_]+):-", (ROOT / "deploy" / script).read_text()))
    table = (ROOT / "docs" / "deploy.md").read_text().split("## What the script reads", 1)[1]
    documented = set(re.findall(r"^\| `([A-Z_]+)`(?:, `([A-Z_]+)`)?", table, re.M))
    named = {n for pair in documented for n in pair if n}
    assert {"PROCESSES", "FIRST_APP_PORT", "MEHANIZMI_PGDATA"} <= read
    assert read <= named, read - named


@pytest.mark.parametrize("line, hidden", [
    ("GET /class?class=AB&key=K1 HTTP/1.1", "K1"),
    ("GET /class?class=X%26key%3DK2&y=1", "K2"),
    ("GET /?%6Bey=K3", "K3"),
    ("GET /?%6b%65%79%3dK4", "K4"),
    ("referrer: /velocity_plans?class=A&student%253DT5%2526lang%3Dsr", "T5"),
    ("POST id_token=T6&state=s", "T6"),
    ("x=1%26%73tudent%3dT7", "T7"),
    ("GET /?%4B%45%59%3DK8", "K8"),  # upper-case letters encoded (issue 81)
    ("GET /?key%25%33%44K9", "K9"),  # "=" encoded twice, its digits too
    ("GET /?KEY=K10&x", "K10"), ("GET /?Student%3DT11", "T11"),
    ("connect() failed, client: 192.168.1.20, server: , request: \"GET / HTTP/1.1\"", "192.168.1.20"),
])
def test_every_form_of_a_secret_is_redacted(line, hidden):
    from deploy.logpipe import redacted

    kept = redacted(line)
    assert hidden not in kept and "…" in kept
