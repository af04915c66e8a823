"""Draws the three buildings (maps/) and writes buildings.jsonl: the police station, the hostel and the
clinic, 30 cases each. Run from this folder: /work/main/.venv/bin/python make_all.py"""
from pathlib import Path

import make_clinic
import make_hostel
import make_police

HERE = Path(__file__).parent
for m in (make_police, make_hostel, make_clinic):
    m.main()
(HERE / "buildings.jsonl").write_text("".join((HERE / f"buildings-{n}.jsonl").read_text()
                                               for n in ("police", "hostel", "clinic")))
for n in ("police", "hostel", "clinic"):
    (HERE / f"buildings-{n}.jsonl").unlink()
