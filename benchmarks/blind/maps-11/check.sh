#!/bin/bash
# All checks on the delivered maps (blind12): prints verify_log content.
cd "$(dirname "$0")"
PY=/work/main/.venv/bin/python
echo '$ verify.py maps'; $PY verify.py maps
echo; echo '$ /work/shared/maps/eval_points.py ./truth_langnav.py maps   (truth vs truth)'
$PY /work/shared/maps/eval_points.py ./truth_langnav.py maps
echo; echo '$ routecheck.py'; $PY routecheck.py
echo; echo '$ igncheck.py maps   (door / passage / space within 0.75 m of an ignore polygon)'; $PY igncheck.py maps
mkdir -p render
for y in maps/*.yaml; do n=$(basename $y .yaml); $PY render_files.py $y render/$n.files.png; done
