#!/usr/bin/env bash
# Several app processes behind nginx, for a class larger than one process serves, sharing
# one class store on PostgreSQL.
#   deploy/start.sh                 # one process per core, nginx on 127.0.0.1:8080
#   PROCESSES=4 PORT=80 HOST=0.0.0.0 deploy/start.sh
#   MEHANIZMI_DATABASE_URL=postgresql+psycopg://user:pass@db/mehanizmi deploy/start.sh
# Without MEHANIZMI_DATABASE_URL it starts a PostgreSQL server of its own, its data in
# MEHANIZMI_PGDATA (default data/postgres), reached on a Unix socket in that folder only.
# An app process that dies is started again (its users reconnect through nginx and resume
# from the store). Ctrl-C (or SIGTERM) stops nginx, every process and that server.
# Several machines (docs/deploy.md, "Several machines"): the same script with a role,
#   deploy/start.sh --role app --database URL    # app processes only, listening on HOST
#   deploy/start.sh --role proxy --upstream HOST:PORT [HOST:PORT …]   # nginx only
# every app host given the same MEHANIZMI_COOKIE_SECRET and MEHANIZMI_LTI_KEY file.
# Logs are kept in MEHANIZMI_LOGS (default data/logs; the folder and files readable by the
# starting user alone; rotated at LOG_BYTES, LOG_KEEP old ones kept; no key or token in
# them). deploy/cli.sh runs the command line against this store. See docs/deploy.md, which
# names every variable read here.
set -euo pipefail
cd "$(dirname "$0")/.."
refuse() { echo "deploy/start.sh: $1" >&2; exit 2; }
ROLE=all
upstreams=()
while [ $# -gt 0 ]; do
  case $1 in
    --role) [ $# -ge 2 ] || refuse "--role needs all, app or proxy"; ROLE=$2; shift 2 ;;
    --database) [ $# -ge 2 ] || refuse "--database needs a PostgreSQL URL"
                export MEHANIZMI_DATABASE_URL=$2; shift 2 ;;
    --upstream) shift
                while [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; do upstreams+=("$1"); shift; done ;;
    *) refuse "unknown argument $1 (--role, --database, --upstream)" ;;
  esac
done
case $ROLE in
  all) [ ${#upstreams[@]} -eq 0 ] || refuse "--upstream is for --role proxy (here the app processes are this machine's)" ;;
  app)
    [ -n "${MEHANIZMI_DATABASE_URL:-}" ] || refuse "--role app needs --database URL (the PostgreSQL every app host shares)"
    [ "${MEHANIZMI_DATABASE_URL#postgresql}" != "$MEHANIZMI_DATABASE_URL" ] || refuse "--database must be a postgresql URL (several hosts share it)"
    [ -n "${MEHANIZMI_COOKIE_SECRET:-}" ] || refuse "--role app needs MEHANIZMI_COOKIE_SECRET, the same on every app host"
    [ -n "${MEHANIZMI_LTI_KEY:-}" ] && [ -f "$MEHANIZMI_LTI_KEY" ] || refuse "--role app needs MEHANIZMI_LTI_KEY, a copy of one key file on every app host (python -m solvers lti tool makes it)"
    [ ${#upstreams[@]} -eq 0 ] || refuse "--upstream is for --role proxy" ;;
  proxy)
    [ ${#upstreams[@]} -gt 0 ] || refuse "--role proxy needs --upstream HOST:PORT for each app process"
    for u in "${upstreams[@]}"; do
      [[ $u =~ ^[A-Za-z0-9.-]+:[0-9]+$ ]] || refuse "--upstream $u: give HOST:PORT"
    done ;;
  *) refuse "--role $ROLE: all, app or proxy" ;;
esac
PROCESSES=${PROCESSES:-$(nproc)}
PORT=${PORT:-8080}
HOST=${HOST:-127.0.0.1}
FIRST=${FIRST_APP_PORT:-8601}
APP=${APP:-asgi.py}  # (bench/floor_class_app.py: the class load test's floor)
sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
wanted=""
[ "$ROLE" = app ] || command -v nginx >/dev/null || wanted="nginx-light"
PG_BIN=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1 || true)
[ "$ROLE" != all ] || [ -n "${MEHANIZMI_DATABASE_URL:-}" ] || [ -n "$PG_BIN" ] || wanted="$wanted postgresql"
if [ -n "$wanted" ]; then
  $sudo apt-get update -q && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q $wanted
  PG_BIN=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1 || true)
fi
[ -d node_modules ] || bash scripts/bundles.sh
if [ ! -x .venv/bin/streamlit ]; then
  python3 -m venv .venv
  .venv/bin/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
fi
.venv/bin/python scripts/icon_font.py  # once per Streamlit version: its icon font, cut
LOGS=${MEHANIZMI_LOGS:-data/logs}
mkdir -p "$LOGS" && chmod 700 "$LOGS" && LOGS=$(cd "$LOGS" && pwd)
logged() {  # a log file fed from a pipe: rotated, private, keys and tokens redacted
  .venv/bin/python deploy/logpipe.py "$LOGS/$1" --bytes "${LOG_BYTES:-10485760}" --keep "${LOG_KEEP:-5}"
}
RUN=$(mktemp -d /tmp/mehanizmi-deploy.XXXXXX)  # nginx's configuration and scratch: removed
[ "$(id -u)" -ne 0 ] || chmod 711 "$RUN"  # (nginx's workers run as nobody)
# one cookie secret for all processes (XSRF, sessions); for several hosts, given to each
SECRET=${MEHANIZMI_COOKIE_SECRET:-$(head -c 32 /dev/urandom | od -An -tx1 | tr -d ' \n')}
pids=()
PGDATA=""
as_postgres=()  # PostgreSQL refuses to run as root
[ "$(id -u)" -eq 0 ] && as_postgres=(runuser -u postgres --)
stop() {
  trap - EXIT
  kill "${pids[@]}" 2>/dev/null || true; wait 2>/dev/null || true
  [ -z "$PGDATA" ] || "${as_postgres[@]}" "$PG_BIN/pg_ctl" -D "$PGDATA" -m fast -w stop >/dev/null || true
  rm -rf "$RUN"
}
trap stop EXIT
trap 'exit 143' INT TERM  # (stop runs on the way out)
PG_QUIET="-c log_error_verbosity=terse -c log_min_error_statement=panic"  # (deploy/cli.sh too)
if [ "$ROLE" = all ] && [ -z "${MEHANIZMI_DATABASE_URL:-}" ]; then  # a server of our own, its data kept
  data=${MEHANIZMI_PGDATA:-data/postgres}
  mkdir -p "$data"
  data=$(cd "$data" && pwd)
  if [ ${#as_postgres[@]} -gt 0 ]; then
    chown postgres "$data"
    "${as_postgres[@]}" test -w "$data" || {
      echo "the postgres user cannot write $data: set MEHANIZMI_PGDATA to a folder it can reach" >&2; exit 1; }
  fi
  [ -f "$data/PG_VERSION" ] || "${as_postgres[@]}" "$PG_BIN/initdb" -D "$data" -A trust -U postgres >/dev/null
  # its socket and its log in its own folder (mode 700): the same path at every start; an
  # error logged without its DETAIL or statement (a unique collision's DETAIL names the
  # student's token)
  "${as_postgres[@]}" "$PG_BIN/pg_ctl" -D "$data" -l "$data/server.log" -w \
    -o "-k $data -c listen_addresses='' $PG_QUIET" start >/dev/null
  PGDATA=$data
  export MEHANIZMI_DATABASE_URL="postgresql+psycopg://postgres@/postgres?host=$data"
fi
if [ "$ROLE" != proxy ]; then  # the schema, made or upgraded before any process serves
  # (app hosts starting together: one migrates under PostgreSQL's advisory lock, the others
  # wait for it and find the schema done)
  .venv/bin/python -m solvers class migrate
fi
LISTEN=127.0.0.1  # the app processes' address: this machine's only, but for --role app
[ "$ROLE" != app ] || LISTEN=$HOST
serve() {  # one app process on port $1, started again if it dies (its users reconnect)
  local port=$1 child=""
  trap 'kill $child 2>/dev/null; wait $child 2>/dev/null; exit 0' TERM
  while true; do
    MEHANIZMI_PROXY_HOST="$HOST" STREAMLIT_SERVER_COOKIE_SECRET="$SECRET" .venv/bin/python scripts/serve.py "$APP" \
      --server.port "$port" --server.address "$LISTEN" --server.headless true \
      > >(logged "app-$port.log") 2>&1 &
    child=$!
    wait $child && code=0 || code=$?
    echo "the app process on port $port stopped (exit $code); starting it again" >&2
    sleep 1
  done
}
servers=""
if [ "$ROLE" = proxy ]; then  # another host's process: passed over for 10 s after one failure
  for upstream in "${upstreams[@]}"; do
    servers+="        server $upstream max_fails=1 fail_timeout=10s;"$'\n'
  done
else  # this machine's: always tried (a process that died is started again within a second)
  for i in $(seq 0 $((PROCESSES - 1))); do
    port=$((FIRST + i))
    serve "$port" &
    pids+=($!)
    servers+="        server 127.0.0.1:$port max_fails=0;"$'\n'
  done
fi
if [ "$ROLE" = app ]; then
  echo "Mehanizmi: $PROCESSES app processes at $HOST:$FIRST and up, for a proxy (logs in $LOGS)"
  wait -n || true
  exit 1
fi
mkdir -p "$RUN"/{body,proxy,fastcgi,uwsgi,scgi}
awk -v run="$RUN" -v port="$PORT" -v host="$HOST" -v servers="$servers" \
  '{gsub("@RUN@", run); gsub("@PORT@", port); gsub("@HOST@", host); sub("@SERVERS@", servers); print}' \
  deploy/nginx.conf.in > "$RUN/nginx.conf"
nginx -t -e stderr -p "$RUN" -c "$RUN/nginx.conf" -q
# its error log on stderr and its access log on stdout, each into a kept, redacted log
nginx -e stderr -p "$RUN" -c "$RUN/nginx.conf" -g "daemon off;" > >(logged access.log) 2> >(logged nginx.log) &
pids+=($!)
if [ "$ROLE" = proxy ]; then
  echo "Mehanizmi: nginx at http://$HOST:$PORT before ${#upstreams[@]} app processes (logs in $LOGS)"
else
  echo "Mehanizmi: $PROCESSES processes behind nginx at http://$HOST:$PORT (logs in $LOGS)"
fi
wait -n || true
echo "nginx stopped; stopping the rest (logs: $LOGS)" >&2
tail -n 20 "$LOGS"/nginx.log "$LOGS"/app-*.log >&2 2>/dev/null || true
