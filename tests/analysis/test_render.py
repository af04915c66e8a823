"""The annotated picture: readable scale, labels that never overlap, names a user types, no
crash at any size, and the same picture as SVG."""

from __future__ import annotations

import itertools
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from analysis_maps import room_with_door

from langnav.analysis.elements import MapAnalysis
from langnav.analysis.pipeline import analyze
from langnav.analysis.render import (
    MAX_PNG_PIXELS,
    LabelItem,
    boxes_overlap,
    display_name,
    frame_for,
    place_labels,
    render_picture,
    save_png,
    save_svg,
    svg_text,
)
from langnav.cli import main as cli_main
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OccupancyGrid


def block_of_offices(cols: int = 8, rows: int = 3) -> OccupancyGrid:
    """``cols`` x ``rows`` offices of 4 x 4 m along east-west corridors 1.6 m wide, each office
    with a 0.9 m door onto the corridor south of it and a 0.6 x 0.6 m box: a big map with
    many labels close together."""
    w, h = cols * 4.15 + 2.0, rows * 5.9 + 2.0
    b = MapBuilder(w, h, origin=(-1.0, -1.0))
    for j in range(rows):
        y0 = j * 5.9
        b.room(0.0, y0, cols * 4.15 - 0.15, y0 + 1.6)
        for i in range(cols):
            x0 = i * 4.15
            b.room(x0, y0 + 1.75, x0 + 4.0, y0 + 5.75)
            b.door_h(x0 + 2.0, y0 + 1.675, 0.9)
            b.box(x0 + 1.0, y0 + 3.0, x0 + 1.6, y0 + 3.6)
    return b.build(source="block_of_offices")


@pytest.fixture(scope="module")
def offices() -> MapAnalysis:
    return analyze(block_of_offices())


def all_names(a: MapAnalysis) -> set[str]:
    return {display_name(e.id) for e in a.elements}


def assert_legible(a: MapAnalysis, max_pixels: int | None = None) -> None:
    pic = render_picture(a) if max_pixels is None else render_picture(a, max_pixels=max_pixels)
    lay = pic.layout
    boxes = [lab.box for lab in lay.labels]
    # No two labels overlap, none covers the scale bar, all lie on the map part of the picture.
    for p, q in itertools.combinations(boxes, 2):
        assert not boxes_overlap(p, q), (p, q)
    mw, mh = lay.frame.size
    for b in boxes:
        assert not boxes_overlap(b, lay.scale_bar[1])
        assert 0 <= b[0] <= b[2] <= mw and 0 <= b[1] <= b[3] <= mh
    # Every element is named once, as a user types it: on the map, or in the legend.
    shown = [lab.text for lab in lay.labels] + [d.text for d in lay.dropped]
    assert sorted(shown) == sorted(all_names(a))
    assert all("_" not in t for t in shown)
    assert pic.image.size == lay.size
    # The map part keeps within the pixel budget (the legend beside it is a fixed width).
    assert mw * mh <= (max_pixels or MAX_PNG_PIXELS)


def test_names_are_what_a_user_types() -> None:
    assert display_name("door_2") == "door 2"
    assert display_name("narrow_passage_10") == "narrow passage 10"


def test_small_map_is_drawn_several_pixels_a_cell() -> None:
    a = analyze(room_with_door())
    frame = frame_for(a)
    assert frame.k == 1 and frame.s >= 4
    assert_legible(a)
    names = {lab.text for lab in render_picture(a).layout.labels}
    assert {"room 1", "door 1"} <= names


def test_large_map_labels_never_overlap(offices: MapAnalysis) -> None:
    assert len(offices.rooms) >= 24 and len(offices.doors) >= 24
    assert_legible(offices)
    lay = render_picture(offices).layout
    # The spaces and doors, most important, all find room on the map.
    placed = {lab.text for lab in lay.labels}
    assert {display_name(r.id) for r in offices.rooms} <= placed
    assert {display_name(d.id) for d in offices.doors} <= placed


def test_huge_map_is_drawn_several_cells_a_pixel_without_failing(offices: MapAnalysis) -> None:
    # A pixel budget far below the map's cells: the picture shrinks, it does not fail.
    cells = offices.grid.width * offices.grid.height
    frame = frame_for(offices, max_pixels=cells // 10)
    assert frame.k >= 3 and frame.s == 1
    assert_legible(offices, max_pixels=cells // 10)


def test_crowded_labels_go_to_the_legend() -> None:
    items = [LabelItem(f"corner {i}", (50.0, 50.0), (0, 0, 0), 5) for i in range(200)]
    items.append(LabelItem("room 1", (50.0, 50.0), (0, 0, 0), 0, centred=True))
    placed, dropped = place_labels(items, (200, 200), lambda t: (7.0 * len(t), 13.0))
    assert placed[0].text == "room 1" and not placed[0].leader
    assert len(placed) + len(dropped) == 201 and dropped
    for p, q in itertools.combinations([lab.box for lab in placed], 2):
        assert not boxes_overlap(p, q)


def test_svg_holds_the_same_labels(offices: MapAnalysis, tmp_path: Path) -> None:
    text, lay = svg_text(offices)
    root = ET.fromstring(text)
    ns = "{http://www.w3.org/2000/svg}"
    texts = [t.text for t in root.iter(f"{ns}text")]
    for lab in lay.labels:
        assert lab.text in texts
    for p, q in itertools.combinations([lab.box for lab in lay.labels], 2):
        assert not boxes_overlap(p, q)
    assert len(list(root.iter(f"{ns}image"))) == 1
    out = save_svg(offices, tmp_path / "o.svg")
    assert out.read_text(encoding="utf-8") == text


@pytest.mark.parametrize("shape", [(1, 400), (400, 1), (3, 3)])
def test_degenerate_grids_render(shape: tuple[int, int]) -> None:
    # A one-cell-thin strip of free space, and a 3 x 3 grid: pictures, not failures.
    cells = np.full(shape, -1, dtype=np.int8)
    cells[shape[0] // 2, :] = 0
    grid = OccupancyGrid(cells, 0.05, source="thin")
    pic = render_picture(analyze(grid))
    assert pic.image.size[0] > 0 and pic.image.size[1] > 0


def test_cli_writes_png_and_svg(tmp_path: Path) -> None:
    png, svg = tmp_path / "a.png", tmp_path / "a.svg"
    assert cli_main(["analyze", "demo", "--png", str(png), "--svg", str(svg)]) == 0
    assert png.stat().st_size > 0 and svg.read_text(encoding="utf-8").startswith("<svg")


def test_save_png_round_trip(tmp_path: Path) -> None:
    a = analyze(room_with_door())
    p = save_png(a, tmp_path / "sub" / "x.png")
    from PIL import Image
    with Image.open(p) as im:
        assert im.size == render_picture(a).image.size
