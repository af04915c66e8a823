"""The simulator's cost scales with what the robot does, not with the map's size: a scan and a
plan touch a window around the robot (and its trip), never a copy of the whole grid."""

from __future__ import annotations

import tracemalloc

import numpy as np

from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid
from langnav.robot import TaskStatus
from langnav.robot.sim import create_sim
from langnav.robot.sim.mapping import LogOddsMap


def corridor_world(n: int = 3000) -> OccupancyGrid:
    """n x n cells of 5 cm, all unknown but a 2 m x 40 m corridor (x 5..45, y 50..52) with walls."""
    cells = np.full((n, n), UNKNOWN, dtype=np.int8)
    cells[998:1042, 98:902] = OCCUPIED
    cells[1000:1040, 100:900] = FREE
    return OccupancyGrid(cells, 0.05, source="corridor")


def test_steps_allocate_a_window_not_the_grid() -> None:
    world = corridor_world()
    s = create_sim(world, (10.0, 51.0, 0.0), known_map=True)
    tracemalloc.start()
    try:
        h = s.move("forward", 30)
        assert h.wait(30).status is TaskStatus.SUCCEEDED
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    # a 9 M-cell grid: one full-grid bool array alone is 9 MB; the scan window is 0.17 M cells
    assert peak < 3_000_000


def test_a_plan_is_searched_near_start_and_goal() -> None:
    s = create_sim(corridor_world(), (10.0, 51.0, 0.0), known_map=True)
    tracemalloc.start()
    try:
        path = s.plan_path((10.0, 51.0), (20.0, 51.0))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert abs(path[-1][0] - 20.0) < 1e-9 and abs(path[-1][1] - 51.0) < 1e-9
    assert all(50.0 < y < 52.0 for _, y in path)
    assert peak < 40_000_000  # a float64 array over the whole grid is 72 MB


def test_the_plan_window_grows_when_the_goal_is_walled_off_in_it() -> None:
    # two corridors 1 m apart, joined only 30 m away: the way round leaves the first window
    cells = np.full((600, 1000), OCCUPIED, dtype=np.int8)
    cells[100:140, 20:980] = FREE      # south corridor, y 5..7
    cells[160:200, 20:980] = FREE      # north corridor, y 8..10
    cells[100:200, 940:980] = FREE     # joined at x 47..49
    s = create_sim(OccupancyGrid(cells, 0.05), (5.0, 6.0, 0.0), known_map=True)
    path = s.plan_path((5.0, 6.0), (5.0, 9.0))
    assert max(x for x, _ in path) > 46.0
    assert path[-1] == (5.0, 9.0)


def test_a_scan_changes_only_cells_within_range() -> None:
    world = corridor_world(1200)
    m = LogOddsMap(world)
    angles = np.linspace(-np.pi, np.pi, 360, endpoint=False)
    win = m.integrate(10.0, 51.0, 0.0, angles, np.full(360, np.inf), 10.0)
    assert win is not None
    rows, cols = win
    assert rows.stop - rows.start <= 2 * (200 + 4) + 1 and cols.stop - cols.start <= 2 * (200 + 4) + 1
    free = m.cells() == FREE
    ys, xs = np.nonzero(free)
    assert free.sum() > 50_000  # 360 beams of 200 cells: nearly every cell near the sensor, fewer far out
    assert ((ys + 0.5 - 1020) ** 2 + (xs + 0.5 - 200) ** 2).max() <= 201 ** 2
    assert m.logodds.max() == 0.0 and m.logodds.min() == -1.5
