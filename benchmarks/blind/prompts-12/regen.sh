#!/usr/bin/env bash
# Regenerate both case files, the maps, the pictures and the self-checks (oracle outputs must score 1.0).
set -eu
cd "$(dirname "$0")"
PY="nice /work/main/.venv/bin/python"   # numpy + scipy + PIL (score.py's Map is imported for the checks)
$PY make_spoken.py                      # spoken.jsonl
$PY make_buildings.py                   # draws maps/{datacentre,gym,bank}.*, checks every region, writes out/buildings.oracle.jsonl
$PY oracle_spoken.py                    # writes out/spoken.oracle.jsonl
$PY negative_test.py                    # deliberately wrong regions must be rejected by the region check
$PY wrong_outputs.py                    # six deliberately wrong outputs must score below 1.0
$PY check_new.py                        # no prompt repeats an earlier one; unexplored areas per map; one component per map
$PY stats.py                            # the mix (counts printed in README.md)
$PY render.py                           # out/*.png
for f in spoken buildings; do
  echo "== oracle $f"; $PY /work/shared/bench/score.py $f.jsonl out/$f.oracle.jsonl
done
