#!/usr/bin/env bash
# Install what the app needs (a local .venv) and start it on http://localhost:8501.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bundles.sh
python3 -m venv .venv
.venv/bin/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
.venv/bin/python scripts/icon_font.py  # once per Streamlit version: its icon font, cut
.venv/bin/python -m solvers class migrate  # the class store's schema (data/ or MEHANIZMI_DATABASE_URL)
exec .venv/bin/python scripts/serve.py asgi.py --server.port 8501 --browser.gatherUsageStats false "$@"
