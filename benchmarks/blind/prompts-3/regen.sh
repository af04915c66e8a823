#!/usr/bin/env bash
# Regenerate both case files, the maps, and the self-checks (oracle outputs must score 1.0).
set -eu
cd "$(dirname "$0")"
PY=/work/main/.venv/bin/python          # numpy + scipy (score.py's Map is imported for the checks)
$PY make_spoken.py
$PY make_buildings.py                   # draws maps/{school,hotel,home}.*, checks every region, writes out/buildings.oracle.jsonl
python3 oracle_spoken.py                # writes out/spoken.oracle.jsonl
for f in spoken buildings; do
  echo "== oracle $f"; $PY /work/shared/bench/score.py $f.jsonl out/$f.oracle.jsonl | head -2
done
