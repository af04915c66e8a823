"""A YAML whose thresholds read the unknown grey (205) as free or occupied is read as map_server
reads it, with a warning naming the value and what to change; ``unknown_grey`` reads it as
unknown."""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pytest

from langnav.cli import main as cli_main
from langnav.maps import FREE, OCCUPIED, UNKNOWN, load_map
from langnav.maps.io import grey_read_as_known

# Image orientation: a 20 x 20 free room with a wall ring, unknown (205) all round it.
IMG = np.full((30, 30), 205, dtype=np.uint8)
IMG[4:26, 4:26] = 0
IMG[5:25, 5:25] = 254


def write_map(tmp_path: Path, free_thresh: float, negate: int = 0, occupied_thresh: float = 0.65) -> Path:
    img = IMG if not negate else 255 - IMG
    if negate:
        img = np.where(IMG == 205, 205, img)  # the grey stays the grey
    (tmp_path / "m.pgm").write_bytes(b"P5\n30 30\n255\n" + img.astype(np.uint8).tobytes())
    y = tmp_path / "m.yaml"
    y.write_text(f"image: m.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: {negate}\n"
                 f"occupied_thresh: {occupied_thresh}\nfree_thresh: {free_thresh}\n", encoding="utf-8")
    return y


def grey_cells(grid_cells: np.ndarray) -> np.ndarray:
    return grid_cells[np.flipud(IMG) == 205]


def test_map_saver_thresholds_read_grey_as_unknown_without_a_word(tmp_path: Path,
                                                                  caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="langnav.maps.io"):
        g = load_map(write_map(tmp_path, 0.196))
    assert (grey_cells(g.cells) == UNKNOWN).all()
    assert caplog.records == []


def test_free_thresh_reading_grey_as_free_is_warned_with_the_fix(tmp_path: Path,
                                                                caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="langnav.maps.io"):
        g = load_map(write_map(tmp_path, 0.25))
    # Read as map_server reads it: the grey is free.
    assert (grey_cells(g.cells) == FREE).all()
    (rec,) = caplog.records
    msg = rec.getMessage()
    n_grey = int(np.count_nonzero(IMG == 205))
    assert "free_thresh 0.25" in msg and "FREE" in msg and f"{n_grey} cells" in msg
    assert "set free_thresh to 0.196" in msg and "--unknown-grey" in msg


def test_unknown_grey_reads_it_as_unknown(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="langnav.maps.io"):
        g = load_map(write_map(tmp_path, 0.25), unknown_grey=True)
    assert (grey_cells(g.cells) == UNKNOWN).all()
    assert (g.cells[np.flipud(IMG) == 254] == FREE).all()
    assert (g.cells[np.flipud(IMG) == 0] == OCCUPIED).all()
    assert caplog.records == []


def test_negated_map_reading_grey_as_occupied_is_warned(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING, logger="langnav.maps.io"):
        g = load_map(write_map(tmp_path, 0.196, negate=1))
    assert (grey_cells(g.cells) == OCCUPIED).all()
    (rec,) = caplog.records
    assert "OCCUPIED" in rec.getMessage() and "occupied_thresh 0.65" in rec.getMessage()


@pytest.mark.parametrize(("negate", "occ", "free", "reads"), [
    (0, 0.65, 0.196, None), (0, 0.65, 0.19607, None), (0, 0.65, 0.1961, "FREE"), (0, 0.65, 0.25, "FREE"),
    (1, 0.65, 0.196, "OCCUPIED"), (1, 0.9, 0.196, None), (0, 0.19, 0.1, "OCCUPIED"),
])
def test_which_thresholds_are_warned(negate: int, occ: float, free: float, reads: str | None) -> None:
    msg = grey_read_as_known(bool(negate), occ, free, 10, 100)
    assert (msg is None) if reads is None else (reads in (msg or ""))


def test_cli_warns_and_offers_the_option(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    y = write_map(tmp_path, 0.25)
    assert cli_main(["analyze", str(y)]) == 0
    assert cli_main(["analyze", str(y), "--unknown-grey"]) == 0
