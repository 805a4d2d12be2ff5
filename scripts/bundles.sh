#!/usr/bin/env bash
# Plotly's partial bundles (package.json, pinned in package-lock.json), served by ui/plot.py:
# a page opens ~1 s sooner with them. Without npm the app serves the full bundle of the
# plotly Python package instead.
set -euo pipefail
cd "$(dirname "$0")/.."
if command -v npm >/dev/null; then
  npm ci --no-audit --no-fund --loglevel=error
else
  echo "warning: no npm here; pages load the full plotly.js bundle (a slower first paint)" >&2
fi
