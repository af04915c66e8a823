"""Malformed and odd maps, through the loader and the whole stack: each one loads and works, or
fails with a MapError / AnalysisError naming the file and the problem; never a traceback."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from PIL import Image

from langnav.analysis.errors import AnalysisError
from langnav.analysis.pipeline import analyze
from langnav.errors import LangnavError
from langnav.maps.errors import MapError
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.maps.io import load_map

GOOD_HEADER = "resolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"


def _room(h: int = 60, w: int = 80) -> np.ndarray:
    """A walled room as a map_saver image (row 0 = top): 0 walls, 254 floor."""
    img = np.zeros((h, w), np.uint8)
    img[5:-5, 5:-5] = 254
    return img


def _pgm(path: Path, img: np.ndarray) -> Path:
    path.write_bytes(f"P5\n{img.shape[1]} {img.shape[0]}\n255\n".encode() + img.tobytes())
    return path


def _yaml(tmp_path: Path, name: str, body: str, image: str = "room.pgm") -> Path:
    if not (tmp_path / "room.pgm").exists():
        _pgm(tmp_path / "room.pgm", _room())
    y = tmp_path / f"{name}.yaml"
    y.write_text(f"image: {image}\n{body}", encoding="utf-8")
    return y


# -- the loader --------------------------------------------------------------------------------
@pytest.mark.parametrize(("name", "body", "expect"), [
    ("negres", "resolution: -0.05\norigin: [0, 0, 0]\n", "resolution -0.05 m/cell is out of range"),
    ("nanorigin", "resolution: 0.05\norigin: [.nan, 0.0, 0.0]\n", "origin must be [x, y, yaw] (finite numbers"),
    ("inforigin", "resolution: 0.05\norigin: [.inf, 0.0, 0.0]\n", "origin must be [x, y, yaw] (finite numbers"),
    ("bigint", "resolution: 0.05\norigin: [" + "9" * 400 + ", 0, 0]\n", "origin must be [x, y, yaw]"),
    ("farorigin", "resolution: 0.05\norigin: [1.0e+300, 0.0, 0]\n", "origin_x_m 1e+300 is beyond"),
    ("listres", "resolution: [0.05, 0.1]\norigin: [0, 0, 0]\n", "resolution must be a finite number"),
    ("dictres", "resolution: {x: 0.05, y: 0.1}\norigin: [0, 0, 0]\n", "resolution must be a finite number"),
    ("strres", "resolution: fine\norigin: [0, 0, 0]\n", "resolution must be a finite number, got 'fine'"),
    ("tinyres", "resolution: 1e-300\norigin: [0, 0, 0]\n", "resolution 1e-300 m/cell is out of range"),
    ("originstr", "resolution: 0.05\norigin: '0,0,0'\n", "origin must be [x, y, yaw]"),
    ("noorigin", "resolution: 0.05\n", "origin must be [x, y, yaw]"),
])
def test_bad_yaml_values_name_the_file_and_the_key(tmp_path: Path, name: str, body: str, expect: str) -> None:
    y = _yaml(tmp_path, name, body)
    with pytest.raises(MapError) as err:
        load_map(y)
    msg = str(err.value)
    assert msg.startswith(str(y)), msg
    assert expect in msg
    assert len(msg) < 300  # a hostile value is quoted short


def test_yaml11_exponent_numbers_read_as_numbers(tmp_path: Path) -> None:
    # PyYAML reads 5e-2 as a string (YAML 1.1); map_server reads it as 0.05
    g = load_map(_yaml(tmp_path, "exp", "resolution: 5e-2\norigin: [1e1, -2E0, 0]\n"))
    assert g.resolution_m == pytest.approx(0.05)
    assert (g.origin_x_m, g.origin_y_m) == (10.0, -2.0)


def test_unknown_keys_are_ignored(tmp_path: Path) -> None:
    g = load_map(_yaml(tmp_path, "extra", GOOD_HEADER + "foo: bar\nsensor: {model: x}\n"))
    assert (g.width, g.height) == (80, 60)


def test_image_that_is_a_directory(tmp_path: Path) -> None:
    (tmp_path / "adir").mkdir()
    with pytest.raises(MapError, match=r"adir: the map image is a directory"):
        load_map(_yaml(tmp_path, "dir", GOOD_HEADER, image="adir"))
    with pytest.raises(MapError, match=r"adir: is a directory"):
        load_map(tmp_path / "adir")


def test_a_path_the_os_refuses(tmp_path: Path) -> None:
    with pytest.raises(MapError, match="cannot use this path"):
        load_map(tmp_path / ("x" * 5000 + ".yaml"))
    with pytest.raises(MapError, match="cannot use this path"):
        load_map(_yaml(tmp_path, "long", GOOD_HEADER, image="y" * 5000 + ".pgm"))


def test_png_with_alpha_and_nonzero_yaw(tmp_path: Path) -> None:
    rgba = np.zeros((60, 80, 4), np.uint8)
    rgba[..., 3] = 255
    rgba[5:55, 5:75, :3] = 254
    Image.fromarray(rgba).save(tmp_path / "a.png")
    y = tmp_path / "a.yaml"
    y.write_text("image: a.png\nresolution: 0.05\norigin: [1.0, 2.0, 0.5]\n", encoding="utf-8")
    g = load_map(y)
    assert g.origin_yaw_rad == 0.5
    assert int(g.free.sum()) == 50 * 70
    a = analyze(g)
    assert len(a.rooms) == 1
    # the room's centre, turned by the yaw: cell (30, 40) centre is 2.025, 1.525 m along the map axes
    cx, cy = a.rooms[0].centroid
    assert cx == pytest.approx(1.0 + math.cos(0.5) * 2.0 - math.sin(0.5) * 1.5, abs=0.1)
    assert cy == pytest.approx(2.0 + math.sin(0.5) * 2.0 + math.cos(0.5) * 1.5, abs=0.1)


@pytest.mark.parametrize("kind", ["png16", "pgm65535"])
def test_sixteen_bit_images(tmp_path: Path, kind: str) -> None:
    wide = _room().astype(np.uint16) * 257
    if kind == "png16":
        Image.fromarray(wide).save(tmp_path / "m.png")
        image = "m.png"
    else:
        (tmp_path / "m.pgm").write_bytes(b"P5\n80 60\n65535\n" + wide.astype(">u2").tobytes())
        image = "m.pgm"
    g = load_map(_yaml(tmp_path, kind, GOOD_HEADER, image=image))
    assert int(g.free.sum()) == 50 * 70
    assert int(g.occupied.sum()) == 80 * 60 - 50 * 70


def test_dark_sixteen_bit_png_stays_occupied(tmp_path: Path) -> None:
    # every value <= 255 of 65535 is nearly black: occupied, not read as 8-bit light grey
    Image.fromarray(np.full((20, 20), 250, np.uint16)).save(tmp_path / "d.png")
    g = load_map(_yaml(tmp_path, "dark", GOOD_HEADER, image="d.png"))
    assert bool(g.occupied.all())


# -- odd but valid grids through analysis ------------------------------------------------------------
def _grid(cells: np.ndarray) -> OccupancyGrid:
    return OccupancyGrid(cells.astype(np.int8), 0.05, source="test-grid")


@pytest.mark.parametrize("cells", [
    np.full((40, 40), OCCUPIED), np.full((40, 40), UNKNOWN)], ids=["no-free", "all-unknown"])
def test_no_free_space_is_a_clear_analysis_error(cells: np.ndarray) -> None:
    with pytest.raises(AnalysisError, match="test-grid: the map has no free space"):
        analyze(_grid(cells))


@pytest.mark.parametrize("shape", [(1, 1), (3, 3), (1, 400), (400, 1)])
def test_tiny_and_thin_maps_analyse_to_nothing(shape: tuple[int, int]) -> None:
    a = analyze(_grid(np.full(shape, FREE)))
    assert len(a.doors) == 0 and len(a.narrow_passages) == 0


def test_one_cell_corridor() -> None:
    cells = np.full((3, 400), OCCUPIED)
    cells[1, 1:-1] = FREE
    a = analyze(_grid(cells))
    assert len(a.rooms) == 0  # narrower than the robot: no space it could use


def test_known_small_grid_that_crashes_analysis() -> None:
    rng = np.random.default_rng(2)
    cells = rng.choice(np.array([FREE, OCCUPIED, UNKNOWN]), size=(21, 7), p=[0.6, 0.25, 0.15])
    analyze(_grid(cells))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(1, 24), st.integers(1, 24), st.integers(0, 2**32 - 1))
def test_random_small_grids_never_crash_analysis(h: int, w: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    cells = rng.choice(np.array([FREE, OCCUPIED, UNKNOWN]), size=(h, w), p=[0.6, 0.25, 0.15])
    try:
        a = analyze(_grid(cells))
    except AnalysisError as exc:
        assert "test-grid" in str(exc)
        return
    assert all(r.area_m2 > 0 for r in a.rooms)


def test_seeded_noise_map_analyses() -> None:
    rng = np.random.default_rng(0)
    cells = rng.choice(np.array([FREE, OCCUPIED, UNKNOWN]), size=(100, 100))
    a = analyze(_grid(cells))
    assert a.grid.width == 100


@pytest.mark.slow
def test_huge_sparse_map_analyses(tmp_path: Path) -> None:
    # map_saver's free_thresh: with the default 0.25 the 205 of unknown reads as free
    # (occ = 50/255 = 0.196), and the whole 200 m x 200 m map is one free room.
    header = GOOD_HEADER + "free_thresh: 0.196\n"
    img = np.full((4000, 4000), 205, np.uint8)
    img[100:140, 100:3500] = 254
    img[99, 100:3500] = 0
    img[140, 100:3500] = 0
    g = load_map(_yaml(tmp_path, "sparse", header, image=_pgm(tmp_path / "sparse.pgm", img).name))
    a = analyze(g)
    assert len(a.rooms) == 1
    assert a.rooms[0].area_m2 == pytest.approx(1.95 * 170.0, rel=0.05)


def test_every_error_is_a_langnav_error(tmp_path: Path) -> None:
    (tmp_path / "bin.yaml").write_bytes(b"\xff\xfe\x00\x01")
    (tmp_path / "trunc.pgm").write_bytes(b"P5\n80 60\n255\n" + b"\xfe" * 100)
    for path in (tmp_path / "bin.yaml", _yaml(tmp_path, "t", GOOD_HEADER, image="trunc.pgm"),
                 _yaml(tmp_path, "self", GOOD_HEADER, image="self.yaml")):
        with pytest.raises(LangnavError) as err:
            load_map(path)
        assert path.name in str(err.value) or "trunc.pgm" in str(err.value)
