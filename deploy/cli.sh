#!/usr/bin/env bash
# The command line (python -m solvers …) against the store deploy/start.sh serves: its own
# PostgreSQL (on the socket in MEHANIZMI_PGDATA, default data/postgres), or the server
# MEHANIZMI_DATABASE_URL names. For example:
#   deploy/cli.sh class export ABC123 --key … > class.csv
#   deploy/cli.sh class summary ABC123 --key …
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${MEHANIZMI_DATABASE_URL:-}" ]; then
  data=${MEHANIZMI_PGDATA:-data/postgres}
  [ -S "$data/.s.PGSQL.5432" ] || {
    echo "no PostgreSQL of deploy/start.sh answers in $data: start it first (or set MEHANIZMI_DATABASE_URL)" >&2
    exit 2; }
  export MEHANIZMI_DATABASE_URL="postgresql+psycopg://postgres@/postgres?host=$(cd "$data" && pwd)"
fi
exec .venv/bin/python -m solvers "$@"
