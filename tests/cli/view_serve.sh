#!/bin/bash
# `sphereset view MESH SPHERES --no-open` prints "sphereset view: http://127.0.0.1:PORT/?token=T"
# and serves until SIGTERM, then exits 0; a build without the page exits 9 with one line instead.
# Usage: view_serve.sh SPHERESET MESH SPHERES
set -u
cli=$1 mesh=$2 spheres=$3
out=$(mktemp) err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
"$cli" view "$mesh" "$spheres" --no-open >"$out" 2>"$err" &
pid=$!
for _ in $(seq 1 600); do  # up to 60 s for the line (the mesh is loaded and certified first)
  grep -q '^sphereset view: ' "$out" && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if ! kill -0 "$pid" 2>/dev/null; then
  wait "$pid"
  rc=$?
  if [ "$rc" = 9 ] && grep -q '^sphereset: this build has no view page' "$err"; then exit 0; fi
  echo "exited $rc before serving: $(cat "$err")"
  exit 1
fi
if ! grep -Eq '^sphereset view: http://127\.0\.0\.1:[0-9]+/\?token=[0-9a-f]{32}$' "$out"; then
  echo "unexpected address line: $(cat "$out")"
  kill "$pid"
  exit 1
fi
kill -TERM "$pid"
wait "$pid"
rc=$?
if [ "$rc" != 0 ]; then
  echo "exit $rc after SIGTERM: $(cat "$err")"
  exit 1
fi
