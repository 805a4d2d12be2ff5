#!/usr/bin/env bash
# Several app processes behind nginx, for a class larger than one process serves.
#   deploy/start.sh                 # one process per core, nginx on 127.0.0.1:8080
#   PROCESSES=4 PORT=80 HOST=0.0.0.0 deploy/start.sh
# Ctrl-C (or SIGTERM) stops nginx and every process. See docs/deploy.md.
set -euo pipefail
cd "$(dirname "$0")/.."
PROCESSES=${PROCESSES:-$(nproc)}
PORT=${PORT:-8080}
HOST=${HOST:-127.0.0.1}
FIRST=${FIRST_APP_PORT:-8601}
if ! command -v nginx >/dev/null; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -q && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q nginx-light
fi
[ -d node_modules ] || bash scripts/bundles.sh
if [ ! -x .venv/bin/streamlit ]; then
  python3 -m venv .venv
  .venv/bin/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
fi
RUN=$(mktemp -d /tmp/mehanizmi-deploy.XXXXXX)
SECRET=$(head -c 32 /dev/urandom | od -An -tx1 | tr -d ' \n')  # one for all processes
pids=()
stop() { kill "${pids[@]}" 2>/dev/null || true; wait 2>/dev/null || true; rm -rf "$RUN"; }
trap stop EXIT INT TERM
servers=""
for i in $(seq 0 $((PROCESSES - 1))); do
  port=$((FIRST + i))
  STREAMLIT_SERVER_COOKIE_SECRET="$SECRET" .venv/bin/python scripts/serve.py app.py \
    --server.port "$port" --server.address 127.0.0.1 --server.headless true \
    > "$RUN/app-$port.log" 2>&1 &
  pids+=($!)
  servers+="        server 127.0.0.1:$port max_fails=0;"$'\n'
done
mkdir -p "$RUN"/{body,proxy,fastcgi,uwsgi,scgi}
awk -v run="$RUN" -v port="$PORT" -v host="$HOST" -v servers="$servers" \
  '{gsub("@RUN@", run); gsub("@PORT@", port); gsub("@HOST@", host); sub("@SERVERS@", servers); print}' \
  deploy/nginx.conf.in > "$RUN/nginx.conf"
nginx -t -p "$RUN" -c "$RUN/nginx.conf" -q
nginx -p "$RUN" -c "$RUN/nginx.conf" -g "daemon off;" &
pids+=($!)
echo "Mehanizmi: $PROCESSES processes behind nginx at http://$HOST:$PORT (logs in $RUN)"
wait -n || true
echo "a process stopped; stopping the rest (logs: $RUN)" >&2
cat "$RUN"/error.log "$RUN"/app-*.log 2>/dev/null | tail -20 >&2
