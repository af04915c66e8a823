"""Map I/O: map_server YAML + images, bare images, ROS arrays, map_saver output, transforms."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

from langnav.maps import (
    FREE,
    OCCUPIED,
    UNKNOWN,
    MapError,
    OccupancyGrid,
    from_ros_data,
    load_map,
    save_map,
    written_resolution,
)
from langnav.maps.io import load_bare_image


def write_pgm(path: Path, img: np.ndarray) -> Path:
    h, w = img.shape
    path.write_bytes(f"P5\n{w} {h}\n255\n".encode() + img.astype(np.uint8).tobytes())
    return path


def write_yaml(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


# Image orientation: row 0 is the top. 0 occupied, 254 free, 205 unknown.
IMG = np.array([[0, 254, 205],
                [254, 254, 0]], dtype=np.uint8)
YAML = "image: m.pgm\nresolution: 0.1\norigin: [1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"


@pytest.fixture
def good_map(tmp_path: Path) -> Path:
    write_pgm(tmp_path / "m.pgm", IMG)
    return write_yaml(tmp_path / "m.yaml", YAML)


def test_trinary_yaml_loads_in_ros_orientation(good_map: Path) -> None:
    g = load_map(good_map)
    assert (g.width, g.height) == (3, 2)
    assert g.resolution_m == 0.1
    assert (g.origin_x_m, g.origin_y_m) == (1.0, 2.0)
    # Bottom row of the grid = last image row.
    assert g.cells.tolist() == [[FREE, FREE, OCCUPIED], [OCCUPIED, FREE, UNKNOWN]]


def test_world_cell_transform_of_loaded_map(good_map: Path) -> None:
    g = load_map(good_map)
    assert g.value_at(1.05, 2.05) == FREE
    assert g.value_at(1.25, 2.05) == OCCUPIED
    assert g.value_at(1.05, 2.15) == OCCUPIED
    assert g.value_at(1.25, 2.15) == UNKNOWN
    assert g.value_at(0.5, 0.5) == UNKNOWN  # outside the grid
    x, y = g.cell_to_world(0, 0)
    assert (float(x), float(y)) == pytest.approx((1.05, 2.05))


@pytest.mark.parametrize(("text", "message"), [
    ("image: m.pgm\nresolution: 0.1\n", "origin"),
    ("resolution: 0.1\norigin: [0, 0, 0]\n", "image"),
    ("image: m.pgm\norigin: [0, 0, 0]\n", "resolution"),
    ("image: m.pgm\nresolution: abc\norigin: [0, 0, 0]\n", "resolution"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nmode: fancy\n", "mode"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 2\n", "negate"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0, 'a', 0]\n", "origin"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0]\n", "origin"),
    ("image: m.pgm\nresolution: 0.1\norigin: [.nan, 0, 0]\n", "origin"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nfree_thresh: 0.9\noccupied_thresh: 0.5\n", "free_thresh"),
    ("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n", "occupied_thresh"),
    ("image: m.pgm\nresolution: 0\norigin: [0, 0, 0]\n", "resolution"),
    ("image: m.pgm\nresolution: 1000\norigin: [0, 0, 0]\n", "resolution"),
    ("image: [unclosed\n", "YAML"),
    ("- just\n- a list\n", "mapping"),
])
def test_malformed_yaml_names_file_and_problem(tmp_path: Path, text: str, message: str) -> None:
    write_pgm(tmp_path / "m.pgm", IMG)
    y = write_yaml(tmp_path / "bad.yaml", text)
    with pytest.raises(MapError) as err:
        load_map(y)
    assert "bad.yaml" in str(err.value)
    assert message in str(err.value)


def test_missing_image_named(tmp_path: Path) -> None:
    y = write_yaml(tmp_path / "m.yaml", YAML)
    with pytest.raises(MapError, match=r"m\.pgm.*not found"):
        load_map(y)


def test_missing_map_file(tmp_path: Path) -> None:
    with pytest.raises(MapError, match="no such file"):
        load_map(tmp_path / "nope.yaml")


def test_unknown_extension(tmp_path: Path) -> None:
    p = tmp_path / "m.txt"
    p.write_text("x")
    with pytest.raises(MapError, match="unknown map type"):
        load_map(p)


def test_bad_image_header(tmp_path: Path) -> None:
    (tmp_path / "m.pgm").write_bytes(b"NOT AN IMAGE AT ALL")
    y = write_yaml(tmp_path / "m.yaml", YAML)
    with pytest.raises(MapError, match=r"m\.pgm"):
        load_map(y)


def test_truncated_pgm(tmp_path: Path) -> None:
    (tmp_path / "m.pgm").write_bytes(b"P5\n100 100\n255\n" + bytes(50))
    y = write_yaml(tmp_path / "m.yaml", YAML)
    with pytest.raises(MapError, match=r"m\.pgm"):
        load_map(y)


def test_absurd_image_size_refused(tmp_path: Path) -> None:
    # A header claiming 100000 x 100000 pixels: refused before any allocation.
    (tmp_path / "m.pgm").write_bytes(b"P5\n100000 100000\n255\n" + bytes(16))
    y = write_yaml(tmp_path / "m.yaml", YAML)
    with pytest.raises(MapError, match=r"m\.pgm"):
        load_map(y)


def test_absurd_ros_array_size_refused() -> None:
    with pytest.raises(MapError, match="more than"):
        from_ros_data(np.zeros(4, dtype=np.int8), 30000, 30000, 0.05)


@pytest.mark.parametrize("res", [0.0, -0.05, float("nan"), 1e6])
def test_absurd_resolution_refused(res: float) -> None:
    with pytest.raises(MapError, match="resolution"):
        OccupancyGrid(np.zeros((2, 2), dtype=np.int8), res)


def test_negate_swaps_free_and_occupied(tmp_path: Path) -> None:
    write_pgm(tmp_path / "m.pgm", IMG)
    y = write_yaml(tmp_path / "m.yaml", YAML.replace("negate: 0", "negate: 1"))
    g = load_map(y)
    # negate: occ = shade; black (0) is free, 254 is occupied, 205 (0.80) is occupied too.
    assert g.cells.tolist() == [[OCCUPIED, OCCUPIED, FREE], [FREE, OCCUPIED, OCCUPIED]]


def test_thresholds_are_used(tmp_path: Path) -> None:
    img = np.array([[100, 180, 230]], dtype=np.uint8)  # occ = 0.61, 0.29, 0.10
    write_pgm(tmp_path / "m.pgm", img)
    y = write_yaml(tmp_path / "m.yaml", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                   "occupied_thresh: 0.5\nfree_thresh: 0.2\n")
    assert load_map(y).cells.tolist() == [[OCCUPIED, UNKNOWN, FREE]]
    y2 = write_yaml(tmp_path / "m2.yaml", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                    "occupied_thresh: 0.65\nfree_thresh: 0.3\n")
    assert load_map(y2).cells.tolist() == [[UNKNOWN, FREE, FREE]]


def test_scale_mode_reduces_in_between_values(tmp_path: Path) -> None:
    img = np.array([[0, 60, 128, 254]], dtype=np.uint8)  # occ 1.0, 0.76, 0.50, 0.004
    write_pgm(tmp_path / "m.pgm", img)
    y = write_yaml(tmp_path / "m.yaml", "image: m.pgm\nmode: scale\nresolution: 0.05\norigin: [0, 0, 0]\n"
                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    # 0.50 is scaled to round((0.5-0.196)/(0.65-0.196)*99) = 66 -> occupied by the ROS 65 % rule.
    assert load_map(y).cells.tolist() == [[OCCUPIED, OCCUPIED, OCCUPIED, FREE]]


def test_scale_mode_transparent_is_unknown(tmp_path: Path) -> None:
    rgba = np.zeros((1, 2, 4), dtype=np.uint8)
    rgba[0, :, :3] = 254
    rgba[0, 0, 3] = 255
    rgba[0, 1, 3] = 0
    Image.fromarray(rgba, mode="RGBA").save(tmp_path / "m.png")
    y = write_yaml(tmp_path / "m.yaml", "image: m.png\nmode: scale\nresolution: 0.05\norigin: [0, 0, 0]\n")
    assert load_map(y).cells.tolist() == [[FREE, UNKNOWN]]


def test_raw_mode_values_are_ros_values(tmp_path: Path) -> None:
    img = np.array([[0, 10, 70, 100, 200]], dtype=np.uint8)
    write_pgm(tmp_path / "m.pgm", img)
    y = write_yaml(tmp_path / "m.yaml", "image: m.pgm\nmode: raw\nresolution: 0.05\norigin: [0, 0, 0]\n")
    assert load_map(y).cells.tolist() == [[FREE, FREE, OCCUPIED, OCCUPIED, UNKNOWN]]


def test_non_zero_yaw_rotates_transforms(tmp_path: Path) -> None:
    write_pgm(tmp_path / "m.pgm", IMG)
    y = write_yaml(tmp_path / "m.yaml", YAML.replace("[1.0, 2.0, 0.0]", f"[1.0, 2.0, {math.pi / 2}]"))
    g = load_map(y)
    assert g.origin_yaw_rad == pytest.approx(math.pi / 2)
    # Cell (0, 0)'s centre is 0.05 along the rotated x (world +y) and 0.05 along rotated y (world -x).
    x, yy = g.cell_to_world(0, 0)
    assert (float(x), float(yy)) == pytest.approx((0.95, 2.05))
    assert g.value_at(0.95, 2.05) == FREE
    assert g.value_at(0.95, 2.25) == OCCUPIED  # cell (0, 2)


def test_bare_image_thresholds(tmp_path: Path) -> None:
    img = np.array([[255, 250, 249, 51, 50, 0]], dtype=np.uint8)
    Image.fromarray(img, mode="L").save(tmp_path / "bare.png")
    g = load_map(tmp_path / "bare.png", resolution_m=0.1)
    assert g.resolution_m == 0.1
    assert g.cells.tolist() == [[FREE, FREE, UNKNOWN, UNKNOWN, OCCUPIED, OCCUPIED]]
    assert load_bare_image(tmp_path / "bare.png").resolution_m == 0.05


def test_bare_rgb_image_uses_mean_shade(tmp_path: Path) -> None:
    rgb = np.array([[[255, 255, 255], [0, 0, 0], [255, 0, 0]]], dtype=np.uint8)
    Image.fromarray(rgb, mode="RGB").save(tmp_path / "bare.png")
    assert load_map(tmp_path / "bare.png").cells.tolist() == [[FREE, OCCUPIED, UNKNOWN]]


def test_from_ros_data_values_and_orientation() -> None:
    data = np.array([-1, 0, 19, 20, 64, 65, 100, 50], dtype=np.int8)
    g = from_ros_data(data, 4, 2, 0.05, 1.0, -1.0)
    assert g.cells.tolist() == [[UNKNOWN, FREE, FREE, UNKNOWN], [UNKNOWN, OCCUPIED, OCCUPIED, UNKNOWN]]
    assert g.to_ros_data().tolist() == [-1, 0, 0, -1, -1, 100, 100, -1]
    # uint8 transport of int8 (-1 arrives as 255).
    g2 = from_ros_data(np.array([255, 0], dtype=np.uint8), 2, 1, 0.05)
    assert g2.cells.tolist() == [[UNKNOWN, FREE]]


@pytest.mark.parametrize(("data", "w", "h", "message"), [
    (np.zeros(5, dtype=np.int8), 2, 2, "expected"),
    (np.array([0, 101, 0, 0]), 2, 2, "values"),
    (np.array([0.0, 1.0, 0.0, 0.0]), 2, 2, "integers"),
    (np.zeros(0, dtype=np.int8), 0, 0, "positive"),
])
def test_from_ros_data_refuses_bad_arrays(data: np.ndarray, w: int, h: int, message: str) -> None:
    with pytest.raises(MapError, match=message):
        from_ros_data(data, w, h, 0.05)


def test_save_map_round_trip_in_map_saver_format(tmp_path: Path) -> None:
    rng = np.random.default_rng(3)
    cells = rng.choice(np.array([FREE, OCCUPIED, UNKNOWN], dtype=np.int8), size=(7, 11))
    g = OccupancyGrid(cells, 0.05, -3.5, 2.25, 0.0)
    y, pgm = save_map(g, tmp_path / "out" / "saved")
    assert y.name == "saved.yaml" and pgm.name == "saved.pgm"
    header = pgm.read_bytes()[:2]
    assert header == b"P5"
    img = np.asarray(Image.open(pgm))
    assert set(np.unique(img).tolist()) <= {0, 205, 254}
    back = load_map(y)
    assert np.array_equal(back.cells, cells)
    assert (back.resolution_m, back.origin_x_m, back.origin_y_m) == (0.05, -3.5, 2.25)


@settings(max_examples=60, deadline=None)
@given(
    x=st.floats(-50, 50), y=st.floats(-50, 50),
    ox=st.floats(-20, 20), oy=st.floats(-20, 20),
    yaw=st.floats(-math.pi, math.pi), res=st.sampled_from([0.01, 0.025, 0.05, 0.1, 0.5]),
)
def test_world_cell_round_trip(x: float, y: float, ox: float, oy: float, yaw: float, res: float) -> None:
    g = OccupancyGrid(np.zeros((4, 5), dtype=np.int8), res, ox, oy, yaw)
    r, c = g.world_to_cell(x, y)
    bx, by = g.grid_to_world(r, c)
    assert float(bx) == pytest.approx(x, abs=1e-9)
    assert float(by) == pytest.approx(y, abs=1e-9)


@settings(max_examples=60, deadline=None)
@given(row=st.integers(-100, 100), col=st.integers(-100, 100), ox=st.floats(-20, 20),
       oy=st.floats(-20, 20), yaw=st.floats(-math.pi, math.pi))
def test_cell_centre_maps_back_to_its_cell(row: int, col: int, ox: float, oy: float, yaw: float) -> None:
    g = OccupancyGrid(np.zeros((3, 3), dtype=np.int8), 0.05, ox, oy, yaw)
    x, y = g.cell_to_world(row, col)
    r, c = g.world_to_index(x, y)
    assert (int(r), int(c)) == (row, col)


def test_resolution_through_a_float32_reads_as_written() -> None:
    """nav_msgs/OccupancyGrid carries the resolution as a float32: 0.05 arrives as 0.0500000007."""
    through_ros = float(np.float32(0.05))
    assert through_ros != 0.05
    g = from_ros_data(np.zeros(4, dtype=np.int8), 2, 2, through_ros)
    assert g.resolution_m == 0.05
    assert written_resolution(float(np.float32(0.025))) == 0.025
    # A value that never went through a float32 is kept as it is.
    assert written_resolution(0.05) == 0.05
    assert written_resolution(0.1 + 1e-12) == 0.1 + 1e-12


def _analysis_summary(grid: OccupancyGrid) -> tuple[object, ...]:
    from langnav.analysis.pipeline import analyze

    a = analyze(grid)
    return (tuple((d.center, d.width_m, d.connects) for d in a.doors), tuple(r.id for r in a.rooms),
            len(a.narrow_passages), len(a.unexplored))


@pytest.mark.parametrize("res", [0.05, 0.025, 0.1, 0.03])
def test_analysis_of_a_map_sent_over_ros_equals_the_saved_one(res: float) -> None:
    """The same floor gives the same doors and rooms from its YAML as from a ROS message."""
    from langnav.maps.draw import MapBuilder

    b = MapBuilder(10.0, 6.0, res, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 4.0).room(4.0, 0.0, 8.0, 4.0)
    b.door_v(4.0, 2.0, 0.9)  # between the two rooms
    b.door_h(1.5, 4.0, 0.875)  # onto the unknown outside, as env1's north door
    saved = b.build(source="two rooms")
    sent = from_ros_data(saved.to_ros_data(), saved.width, saved.height, float(np.float32(res)),
                         saved.origin_x_m, saved.origin_y_m)
    assert _analysis_summary(sent) == _analysis_summary(saved)


def test_bench_env1_over_ros_has_the_doors_of_its_yaml(shared_dir: Path) -> None:
    """env1 lost its north door when its 0.05 m cells arrived as a float32 (make test-ros2)."""
    saved = load_map(shared_dir / "bench" / "maps" / "env1.yaml")
    sent = from_ros_data(saved.to_ros_data(), saved.width, saved.height, float(np.float32(saved.resolution_m)),
                         saved.origin_x_m, saved.origin_y_m)
    assert _analysis_summary(sent) == _analysis_summary(saved)
