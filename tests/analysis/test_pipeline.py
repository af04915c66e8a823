"""The whole analysis: built maps end to end, origin shifts, the golden JSON, the cache, the CLI."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest
from analysis_maps import corridor_with_side_passage, l_room, room_with_door
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

from langnav.analysis import AnalysisCache, analyze
from langnav.analysis.elements import MapAnalysis, reference_point
from langnav.cli import main as cli_main
from langnav.maps.demo import build_demo_grid, demo_map_path
from langnav.maps.io import load_map

GOLDEN = Path(__file__).parent / "golden"
#: Set LANGNAV_UPDATE_GOLDEN=1 to rewrite the golden files after an intended change.
UPDATE = os.environ.get("LANGNAV_UPDATE_GOLDEN") == "1"


def test_room_with_door_end_to_end() -> None:
    a = analyze(room_with_door())
    assert [r.kind.value for r in a.rooms] == ["room"]
    assert len(a.doors) == 1
    d = a.doors[0]
    assert d.center == pytest.approx((4.075, 1.5), abs=0.1)
    assert d.width_m == pytest.approx(0.9, abs=0.06)
    outside = [u for u in a.unexplored if not u.interior]
    assert len(outside) == 1
    # The door opens onto the outside world: connects names it, not "unknown".
    assert set(d.connects) == {a.rooms[0].id, outside[0].id}
    assert [(round(o.centroid[0], 2), round(o.centroid[1], 2)) for o in a.obstacles] == [(1.25, 1.2)]
    assert all(o.room == a.rooms[0].id for o in a.obstacles)
    # (0, 3) is under the unscanned patch: the west and north walls, followed across it, meet there.
    assert sorted((round(c.point[0], 2), round(c.point[1], 2)) for c in a.corners) == [
        (0.0, 0.0), (0.0, 3.0), (4.0, 0.0), (4.0, 3.0)]
    assert all(c.room == a.rooms[0].id for c in a.corners)
    assert a.narrow_passages == ()


def test_l_room_end_to_end() -> None:
    a = analyze(l_room())
    assert len(a.rooms) >= 1
    assert len(a.corners) == 5
    assert len(a.walls) == 6
    assert a.obstacles == () and a.unexplored == () and a.narrow_passages == ()


def test_corridor_side_passage_end_to_end() -> None:
    a = analyze(corridor_with_side_passage())
    assert len(a.narrow_passages) == 1
    p = a.narrow_passages[0]
    assert p.center == pytest.approx((5.0, 2.6), abs=0.15)
    assert p.width_m == pytest.approx(0.7, abs=1e-6)


def _points(a: MapAnalysis) -> dict[str, tuple[float, float]]:
    pts = {e.id: reference_point(e) for e in a.elements}
    for w in a.walls:
        pts[w.id + ":start"] = w.start
        pts[w.id + ":end"] = w.end
    for c in a.corners:
        pts[c.id + ":approach"] = c.approach
    for p in a.narrow_passages:
        pts[p.id + ":end0"], pts[p.id + ":end1"] = p.ends
    return pts


@settings(max_examples=4, deadline=None)
@given(dx=st.floats(-50, 50), dy=st.floats(-50, 50))
def test_shifting_the_origin_shifts_every_element(dx: float, dy: float) -> None:
    grid = room_with_door()
    a = analyze(grid)
    b = analyze(grid.translated(dx, dy))
    pa, pb = _points(a), _points(b)
    assert pa.keys() == pb.keys()
    for k, (x, y) in pa.items():
        assert pb[k] == pytest.approx((x + dx, y + dy), abs=1e-6), k
    assert [len(u.frontier) for u in a.unexplored] == [len(u.frontier) for u in b.unexplored]
    for ua, ub in zip(a.unexplored, b.unexplored, strict=True):
        assert np.allclose(ub.frontier, ua.frontier + np.array([dx, dy]))


def _golden_view(doc: dict) -> dict:
    """The analysis JSON, with rooms and doors reduced to identity and topology: their geometry
    belongs to the segmentation, whose own tests pin it down."""
    out = dict(doc)
    out["rooms"] = [{k: r[k] for k in ("id", "label", "kind")} for r in doc["rooms"]]
    out["doors"] = [{k: d[k] for k in ("id", "connects")} for d in doc["doors"]]
    return out


def test_golden_json_of_built_map() -> None:
    got = _golden_view(json.loads(json.dumps(analyze(room_with_door()).to_json())))
    path = GOLDEN / "room_with_door.json"
    if UPDATE or not path.exists():
        path.write_text(json.dumps(got, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    expected = json.loads(path.read_text(encoding="utf-8"))
    assert got == expected


def test_cache_reuses_analysis_and_keys_by_content() -> None:
    cache = AnalysisCache(max_entries=2)
    g = room_with_door()
    first = cache.get(g)
    assert cache.get(room_with_door()) is first  # same content, another object
    assert (cache.hits, cache.misses) == (1, 1)
    moved = cache.get(g.translated(1.0, 0.0))
    assert moved is not first
    cache.get(l_room())
    assert len(cache) == 2
    assert cache.get(g) is not first  # evicted (least recently used)


def test_demo_files_match_the_builder() -> None:
    grid = load_map(demo_map_path())
    built = build_demo_grid()
    assert np.array_equal(grid.cells, built.cells)
    assert (grid.origin_x_m, grid.origin_y_m, grid.resolution_m) == (built.origin_x_m, built.origin_y_m, 0.05)


def test_cli_analyze_writes_json_png_labels(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out_json, out_png, out_npy = tmp_path / "a.json", tmp_path / "a.png", tmp_path / "l.npy"
    rc = cli_main(["analyze", "demo", "--json", str(out_json), "--png", str(out_png), "--labels", str(out_npy)])
    assert rc == 0
    printed = capsys.readouterr().out
    assert "rooms" in printed and "doors" in printed
    doc = json.loads(out_json.read_text())
    for key in ("rooms", "doors", "walls", "corners", "obstacles", "narrow_passages", "unexplored"):
        assert isinstance(doc[key], list) and doc[key], key
    assert {"id", "label", "kind", "area_m2", "centroid"} <= doc["rooms"][0].keys()
    assert {"id", "center", "width_m", "connects"} <= doc["doors"][0].keys()
    assert {"id", "centroid", "area_m2", "frontier"} <= doc["unexplored"][0].keys()
    grid = load_map(demo_map_path())
    labels = np.load(out_npy)
    assert labels.dtype == np.int32 and labels.shape == (grid.height, grid.width)
    # Image orientation: row 0 is the top, so a room centroid's label sits at the flipped row.
    for room in doc["rooms"]:
        r, c = grid.world_to_index(*room["centroid"])
        if labels[grid.height - 1 - int(r), int(c)] != 0:
            assert labels[grid.height - 1 - int(r), int(c)] == room["label"]
    assert set(np.unique(labels).tolist()) == {0, *[r["label"] for r in doc["rooms"]]}
    with Image.open(out_png) as im:
        assert im.format == "PNG"
        assert im.width >= grid.width * 3  # small maps are scaled up for readable labels


def test_cli_reports_a_broken_map(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    rc = cli_main(["analyze", str(tmp_path / "missing.yaml")])
    assert rc == 2
    assert "missing.yaml" in capsys.readouterr().err
