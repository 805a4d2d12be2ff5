#!/usr/bin/env bash
# Install everything the tests need and run the whole suite (this is what CI runs).
# Debian's chromium serves the browser tests; Playwright never downloads a browser. npm
# installs Plotly's partial bundles (scripts/bundles.sh), which the tests check are served.
set -euo pipefail
cd "$(dirname "$0")/.."
# (PostgreSQL: the class store's tests run against a real server they start themselves;
# nginx: deploy/start.sh is tested as a faculty runs it; iproute2: several machines made of
# network namespaces, tests/test_across_hosts.py)
if [ ! -x /usr/bin/chromium ] || ! command -v npm >/dev/null || ! command -v nginx >/dev/null \
    || ! ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1 || ! command -v ip >/dev/null; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  if command -v apt-get >/dev/null; then
    wanted="chromium chromium-driver fonts-dejavu-core postgresql nginx-light iproute2"
    # Debian's npm conflicts with a Node.js installed from elsewhere that brings its own npm.
    command -v npm >/dev/null || wanted="$wanted npm"
    $sudo apt-get update -q
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q $wanted
  else
    echo "warning: no apt-get here; browser tests need /usr/bin/chromium, npm, postgresql and nginx" >&2
  fi
fi
bash scripts/bundles.sh
python3 -m venv .venv
# --no-compile: Python compiles what is imported, on import; compiling every installed file
# (plotly alone ships thousands) took about twenty seconds of a fresh clone's run
.venv/bin/python -m pip install --quiet --disable-pip-version-check --no-compile -r requirements-dev.txt
.venv/bin/python scripts/icon_font.py  # once per Streamlit version: its icon font, cut
exec .venv/bin/python -m pytest "$@"
