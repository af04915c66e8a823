"""Wall lines (issue 8): door-wide gaps in the building's walls part the spaces on their two
sides, on golden buildings drawn here with exactly known spaces and openings: offices opening
onto a corridor through glass fronts as wide as the corridor, a house's bedroom wing behind a
wide opening, and a corridor T-junction that must not be cut."""

from __future__ import annotations

import math

import numpy as np
import pytest
from analysis_maps import POS_TOL_M, door_near, scan_noise, space_at, turned
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import ndimage as ndi

from langnav.analysis.elements import ElementKind
from langnav.analysis.params import DEFAULT_PARAMS
from langnav.analysis.seg_doors import SEEN_FLOOR_MIN_M
from langnav.analysis.segmentation import UNKNOWN_ID, segment_spaces
from langnav.analysis.wall_lines import (
    WallDirections,
    _line_scores,
    dominant_directions,
    outer_gaps,
)
from langnav.maps.draw import MapBuilder
from langnav.maps.grid import FREE, OCCUPIED, UNKNOWN, OccupancyGrid


def glass_fronted_offices() -> tuple[OccupancyGrid, list[float]]:
    """A 1.6 m corridor, 19.65 m long, with four 4.8 m x 5.4 m offices along its north side.
    Each opens onto it through a 1.8 m front (wider than the corridor), the rest of the wall
    line is glass: 0.9 m panes scanned as wall, broken by 0.2 m laser gaps. Returns the grid
    and the x of each front's centre (on y = 2.675)."""
    b = MapBuilder(21.0, 9.5)
    b.room(0.5, 1.0, 20.15, 2.6)  # the corridor
    fronts = []
    for x0 in (0.5, 5.45, 10.4, 15.35):
        b.room(x0, 2.75, x0 + 4.8, 8.15)
        fronts.append(x0 + 2.4)
    for x in fronts:
        b.door_h(x, 2.675, 1.8)
        for side in (-1.0, 1.0):  # laser gaps between the panes
            b.door_h(x + side * 2.0, 2.675, 0.2)
    return b.build("glass-fronted offices"), fronts


def test_offices_opening_through_fronts_in_a_wall_line_are_rooms_off_the_hallway() -> None:
    """The corridor does not rise above an opening wider than it, so its clearance cannot tell
    it from the offices; the wall line running on past both ends of each front can: each office
    is a room, joined to the hallway through its front (a door: an opening 1.8 m wide cut in the
    wall, as wide as a double door)."""
    grid, fronts = glass_fronted_offices()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 10.0, 1.8)
    assert corridor.kind == ElementKind.HALLWAY
    offices = [space_at(seg, grid, x, 5.0) for x in fronts]
    assert [o.kind for o in offices] == [ElementKind.ROOM] * 4
    assert len({corridor.id, *(o.id for o in offices)}) == 5
    assert len(seg.rooms) == 5
    assert seg.openings == ()
    assert len(seg.doors) == 4
    for x, office in zip(fronts, offices, strict=True):
        d = door_near(seg.doors, x, 2.65)
        assert set(d.connects) == {corridor.id, office.id}
        assert d.width_m == pytest.approx(1.8, abs=POS_TOL_M)


def house_wing() -> OccupancyGrid:
    """An 8 m x 4.9 m living room; past a 1.8 m opening in its north wall, a 1.4 m hallway
    (the bedroom wing) with two bedrooms off it through 0.9 m doors."""
    b = MapBuilder(12.0, 11.0)
    b.room(0.5, 0.5, 8.5, 5.4)  # living room
    b.room(0.5, 5.55, 8.5, 6.95)  # the wing's hallway
    b.door_h(4.0, 5.475, 1.8)  # the wide opening
    b.room(0.5, 7.1, 4.0, 10.5).door_h(2.0, 7.025, 0.9)
    b.room(4.15, 7.1, 8.5, 10.5).door_h(6.5, 7.025, 0.9)
    return b.build("house wing")


def test_a_bedroom_wing_behind_a_wide_opening_is_a_hallway_of_its_own() -> None:
    grid = house_wing()
    seg = segment_spaces(grid)
    living = space_at(seg, grid, 4.0, 3.0)
    wing = space_at(seg, grid, 4.0, 6.25)
    beds = [space_at(seg, grid, 2.0, 9.0), space_at(seg, grid, 6.5, 9.0)]
    assert living.kind == ElementKind.ROOM
    assert wing.kind == ElementKind.HALLWAY
    assert [b.kind for b in beds] == [ElementKind.ROOM] * 2
    assert len({living.id, wing.id, *(b.id for b in beds)}) == 4
    assert len(seg.rooms) == 4
    assert living.area_m2 == pytest.approx(8.0 * 4.9, rel=0.03)
    # The 1.8 m opening is cut in the wall: a door as wide as a double door.
    opening = door_near(seg.doors, 4.0, 5.475)
    assert set(opening.connects) == {living.id, wing.id}
    assert opening.width_m == pytest.approx(1.8, abs=POS_TOL_M)
    assert seg.openings == ()
    assert len(seg.doors) == 3
    for (x, y), bed in zip(((2.0, 7.025), (6.5, 7.025)), beds, strict=True):
        d = door_near(seg.doors, x, y)
        assert set(d.connects) == {wing.id, bed.id}
        assert d.width_m == pytest.approx(0.9, abs=POS_TOL_M)


def home_with_an_arch(arch_m: float, hollow: bool) -> OccupancyGrid:
    """A 16 m x 11 m home: a wall 6 m from its west side runs its whole depth, with an arch
    ``arch_m`` wide cut in it 4 m from the south (the bedroom wing west of it, the living room
    east). ``hollow``: the wall drawn as two faces with its unscanned inside between them (a
    simulator's thick wall), else one solid line."""
    b = MapBuilder(18.0, 13.0)
    b.room(1.0, 1.0, 17.0, 12.0)
    for y0, y1 in ((1.0, 5.0), (5.0 + arch_m, 12.0)):
        if hollow:
            b.rect(6.85, y0, 7.15, y1, OCCUPIED).unknown(6.9, y0, 7.1, y1)
        else:
            b.wall(7.0, y0, 7.0, y1)
    return b.build("home with an arch")


@pytest.mark.parametrize("hollow", [False, True])
@pytest.mark.parametrize("degrees", [0.0, 23.0, 62.0])
def test_a_wing_behind_an_arch_cut_in_a_wall_is_a_room_of_its_own(hollow: bool, degrees: float) -> None:
    """A 3.3 m arch, wider than a double door, in a wall that runs on solid past both of its
    ends for longer than half its width (aws_small_house's bedroom wing): the wing and the
    living room are two rooms with an opening between them, whatever the map's rotation,
    the scan's noise or whether the wall's inside was scanned."""
    grid = home_with_an_arch(3.3, hollow)
    if degrees:
        grid = scan_noise(turned(grid, degrees))
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 2
    assert [r.kind for r in seg.rooms] == [ElementKind.ROOM] * 2
    wing, living = sorted(seg.rooms, key=lambda r: r.area_m2)
    assert wing.area_m2 == pytest.approx(6.0 * 11.0, rel=0.03)
    assert living.area_m2 == pytest.approx(10.0 * 11.0, rel=0.03)
    assert seg.doors == ()
    [arch] = seg.openings
    assert set(arch.connects) == {wing.id, living.id}
    # Its clear width: 3.3 m (3.15 m past a line wall's rounded ends); on a turned, noisy map
    # the stair-stepped wall and its specks take up to 0.4 m of it.
    assert (3.3 if hollow else 3.15) - 0.45 <= arch.width_m <= 3.3 + 0.1


@pytest.mark.parametrize("hollow", [False, True])
def test_an_opening_wider_than_an_arch_or_between_cabinets_joins_one_open_plan(hollow: bool) -> None:
    """A 5 m opening (wider than an arch: an open plan's short stubs either side) is no
    boundary, and nor is a 3.3 m gap in a row of cabinets standing in line (dashed: furniture,
    not a wall): one room each time."""
    assert len(segment_spaces(home_with_an_arch(5.0, hollow)).rooms) == 1
    b = MapBuilder(18.0, 13.0)
    b.room(1.0, 1.0, 17.0, 12.0)
    for y0, y1 in ((1.0, 5.0), (8.3, 12.0)):
        y = y0
        while y < y1 - 0.3:
            b.box(6.8, y, 7.2, min(y + 0.5, y1))  # 0.5 m cabinets, 0.3 m apart
            y += 0.8
    assert len(segment_spaces(b.build("cabinet row")).rooms) == 1


def test_wide_gaps_between_free_standing_screens_are_no_arches() -> None:
    """Desk pods in an open-plan office: solid screens standing free on the floor, 3.3 m apart
    along lines as long as an arch's walls (b7_call_centre). They are joined to no wall of the
    building, so the gaps between them are aisles of one open floor, not arches."""
    b = MapBuilder(18.0, 13.0)
    b.room(1.0, 1.0, 17.0, 12.0)
    for x in (6.0, 9.0, 12.0):
        b.wall(x, 3.0, x, 5.0).wall(x, 8.3, x, 10.3)
        b.wall(x - 0.8, 3.0, x + 0.8, 3.0).wall(x - 0.8, 10.3, x + 0.8, 10.3)
    seg = segment_spaces(b.build("desk pods"))
    assert len(seg.rooms) == 1
    assert seg.doors == () and seg.openings == ()


def t_junction() -> OccupancyGrid:
    """A 1.8 m corridor running east-west, a 1.8 m branch meeting it from the south through
    the whole width of the branch (a gap in the corridor's south wall line, which runs on both
    sides of it), and three offices off them through 0.9 m doors."""
    b = MapBuilder(20.0, 14.0)
    b.room(0.5, 6.0, 19.5, 7.8)  # main corridor
    b.room(9.1, 0.5, 10.9, 5.9)  # the branch
    b.free(9.1, 5.85, 10.9, 6.05)  # where the branch meets the corridor
    b.room(2.0, 7.95, 6.0, 12.0).door_h(4.0, 7.875, 0.9)
    b.room(13.0, 7.95, 17.0, 12.0).door_h(15.0, 7.875, 0.9)
    b.room(3.0, 0.5, 8.9, 5.85).door_h(6.0, 5.925, 0.9)
    return b.build("T-junction")


def test_a_corridor_t_junction_is_not_cut_at_the_gap_in_the_wall_line() -> None:
    """Where a corridor meets another through its whole width there is no door: the branch
    does not run on along the wall line past the gap's ends, as a room behind a door does."""
    grid = t_junction()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 2.0, 6.9)
    assert space_at(seg, grid, 10.0, 2.0) is corridor  # the branch
    assert space_at(seg, grid, 18.0, 6.9) is corridor
    assert corridor.kind == ElementKind.HALLWAY
    offices = [space_at(seg, grid, x, y) for x, y in ((4.0, 10.0), (15.0, 10.0), (6.0, 3.0))]
    assert [o.kind for o in offices] == [ElementKind.ROOM] * 3
    assert len(seg.rooms) == 4
    assert seg.openings == ()
    assert len(seg.doors) == 3
    for (x, y), office in zip(((4.0, 7.875), (15.0, 7.875), (6.0, 5.925)), offices, strict=True):
        d = door_near(seg.doors, x, y)
        assert set(d.connects) == {corridor.id, office.id}


@pytest.mark.parametrize("angle_deg", [0.0, 23.0, 49.0, 87.0])
def test_the_wall_directions_of_a_rotated_building_are_found(angle_deg: float) -> None:
    """Two walls at right angles, rotated by ``angle_deg``: the directions are that angle and
    its right angle, to a fraction of a degree."""
    h = w = 200
    rows, cols = np.mgrid[0:h, 0:w]
    t = math.radians(angle_deg)
    u = (cols - 100) * math.cos(t) + (rows - 100) * math.sin(t)
    v = -(cols - 100) * math.sin(t) + (rows - 100) * math.cos(t)
    wall = ((np.abs(v) <= 1.5) & (np.abs(u) <= 80)) | ((np.abs(u - 30) <= 1.5) & (np.abs(v) <= 60))
    dirs = [math.degrees(d) for d in dominant_directions(wall)]
    assert len(dirs) == 2
    off = (dirs[0] - angle_deg + 45.0) % 90.0 - 45.0  # the same direction modulo 90 degrees
    assert abs(off) <= 0.2
    assert dirs[1] - dirs[0] == pytest.approx(90.0)


def test_wall_directions_kept_with_their_walls_are_reused_only_for_those_walls() -> None:
    """The directions kept with a wall mask are given back for an equal mask (another array),
    and found anew for any other mask."""
    wall = np.zeros((60, 80), dtype=bool)
    wall[10, 5:75] = True
    wall[10:50, 40] = True
    kept = WallDirections(wall, [0.25, 0.25 + math.pi / 2])  # not what the walls say: marks reuse
    assert kept.of(wall.copy()) == [0.25, 0.25 + math.pi / 2]
    other = wall.copy()
    other[30, 60] = True
    assert kept.of(other) == dominant_directions(other)
    assert kept.of(other) != [0.25, 0.25 + math.pi / 2]
    assert kept.of(np.zeros((80, 60), dtype=bool)) == []


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 300), st.integers(0, 300)), min_size=2, max_size=60, unique=True),
       st.lists(st.floats(-1.0, 91.0), min_size=1, max_size=25))
def test_line_scores_count_the_cells_on_each_line(cells: list[tuple[int, int]], degs: list[float]) -> None:
    """Each direction's score is the sum of squared counts of cells per line (the line number
    rounded half to even, as np.rint does), over the number of cells: computed directly here."""
    rows = np.array([r for r, _ in cells], dtype=np.float64)
    neg_cols = -np.array([c for _, c in cells], dtype=np.float64)
    got = _line_scores(rows, neg_cols, np.array(degs))
    for d, score in zip(degs, got.tolist(), strict=True):
        t = math.radians(d)
        total = 0
        for c, s in ((math.cos(t), math.sin(t)), (-math.sin(t), math.cos(t))):
            _, counts = np.unique(np.rint(s * neg_cols + c * rows), return_counts=True)
            total += int((counts * counts).sum())
        assert score == total / rows.size


def narrow_hallway_with_rooms() -> OccupancyGrid:
    """A 1.0 m hallway, 11 m long, 0.2 m walls, with two 3 m x 3 m rooms off it: one through a
    0.7 m doorway (a bathroom's), one through a 0.9 m door."""
    b = MapBuilder(12.0, 8.0)
    b.room(0.5, 0.5, 11.5, 1.5, wall_m=0.2)
    b.room(3.0, 1.7, 6.0, 4.7, wall_m=0.2)
    b.room(6.2, 1.7, 9.0, 4.7, wall_m=0.2)
    b.door_h(4.5, 1.6, 0.7, depth_m=0.3)
    b.door_h(7.5, 1.6, 0.9, depth_m=0.3)
    return b.build("narrow hallway")


def test_a_room_off_a_narrow_hallway_through_a_narrow_doorway_is_a_room_of_its_own() -> None:
    """The hallway is hardly wider than the doorway, so the flood sees no saddle there; the
    doorway is a gap in the hallway's wall line, with the room running on past its ends."""
    grid = narrow_hallway_with_rooms()
    seg = segment_spaces(grid)
    hallway = space_at(seg, grid, 1.5, 1.0)
    assert hallway.kind == ElementKind.HALLWAY
    rooms = [space_at(seg, grid, 4.5, 3.2), space_at(seg, grid, 7.5, 3.2)]
    assert [r.kind for r in rooms] == [ElementKind.ROOM] * 2
    assert len({hallway.id, *(r.id for r in rooms)}) == 3
    assert len(seg.rooms) == 3
    assert len(seg.doors) == 2
    for (x, width), room in zip(((4.5, 0.7), (7.5, 0.9)), rooms, strict=True):
        d = door_near(seg.doors, x, 1.6)
        assert set(d.connects) == {hallway.id, room.id}
        assert d.width_m == pytest.approx(width, abs=POS_TOL_M)


def hall_with_a_rack_row() -> OccupancyGrid:
    """A 20 m x 12 m hall crossed from wall to wall by a row of rack uprights: 0.8 m pieces,
    0.1 m thick, with 1.2 m gaps between them (the lidar sees the uprights and beams at its
    height, not the goods)."""
    b = MapBuilder(22.0, 14.0)
    b.room(1.0, 1.0, 21.0, 13.0)
    x = 1.0
    while x < 21.0:
        b.box(x, 6.95, min(x + 0.8, 21.0), 7.05)
        x += 2.0
    return b.build("hall with a rack row")


def test_a_row_of_racks_with_a_gap_every_few_metres_does_not_split_a_hall() -> None:
    """The row is a dashed line with door-wide gaps and floor on both sides, as a glass wall
    would be, but it is open for more than half its length, every two metres: a row of things
    standing in the hall, not a wall with doors. One room, no doors."""
    grid = hall_with_a_rack_row()
    seg = segment_spaces(grid)
    assert len(seg.rooms) == 1
    assert seg.rooms[0].kind == ElementKind.ROOM
    assert space_at(seg, grid, 10.0, 3.0) is space_at(seg, grid, 10.0, 11.0)
    assert seg.doors == ()
    assert seg.openings == ()


def room_with_a_door_seen_through(fan_half_deg: float = 35.0) -> OccupancyGrid:
    """A 6 m x 4 m room with a 1.0 m door at y = 2 in its east wall (x = 6.05, 0.1 m thick). The
    lidar saw out through it: a fan of rays spreading fan_half_deg either side for 4 m into the
    unscanned outside (its frontier runs metres long, too long for a door-wide saddle)."""
    b = MapBuilder(14.0, 8.0, origin=(-1.0, -2.0))
    b.room(0.0, 0.0, 6.0, 4.0).door_v(6.05, 2.0, 1.0, depth_m=0.2)
    grid = b.build("door seen through")
    cells = grid.cells.copy()
    rows, cols = np.mgrid[0:cells.shape[0], 0:cells.shape[1]]
    x = grid.origin_x_m + (cols + 0.5) * grid.resolution_m - 6.1
    y = grid.origin_y_m + (rows + 0.5) * grid.resolution_m - 2.0
    fan = (x > 0) & (np.abs(np.degrees(np.arctan2(y, x))) <= fan_half_deg) & (np.hypot(x, y) <= 4.0)
    cells[fan & (cells == UNKNOWN)] = FREE
    return OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, source=grid.source)


def test_a_door_the_lidar_saw_out_through_is_a_door_into_unexplored_territory() -> None:
    """The gap in the outer wall's line, with the room's seen floor inside and only the fan of
    rays outside, is the one door, from the room to the unexplored."""
    grid = room_with_a_door_seen_through()
    seg = segment_spaces(grid)
    room = space_at(seg, grid, 3.0, 2.0)
    assert len(seg.doors) == 1
    door = door_near(seg.doors, 6.05, 2.0)
    assert door.connects == (room.id, UNKNOWN_ID)
    assert door.width_m == pytest.approx(1.0, abs=POS_TOL_M)


def seen_masks(grid: OccupancyGrid) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(wall, free, seen floor, unknown) of a grid: seen = free at least SEEN_FLOOR_MIN_M from
    unknown."""
    free, unknown = grid.cells == FREE, grid.cells == UNKNOWN
    seen = free & (ndi.distance_transform_edt(~unknown) * grid.resolution_m >= SEEN_FLOOR_MIN_M)
    return grid.cells == OCCUPIED, free, seen, unknown


def test_outer_gaps_find_the_door_in_the_wall_line_once_per_line() -> None:
    grid = room_with_a_door_seen_through()
    gaps = outer_gaps(*seen_masks(grid), grid.resolution_m, DEFAULT_PARAMS)
    assert gaps  # the wall line is a band of cells: the gap may be read on each of its lines
    for g in gaps:
        x, y = grid.grid_to_world(*g.center_rc)
        assert math.dist((float(x), float(y)), (6.05, 2.0)) <= POS_TOL_M
        assert g.width_m == pytest.approx(1.0, abs=POS_TOL_M)
        assert g.normal_rc[1] > 0.99  # from the room out (east: +col)


def corridor_leaving_a_room() -> OccupancyGrid:
    """A 6 m x 4 m room; a 1.6 m corridor leaves it east through a 1.2 m gap in its wall (jamb
    stubs narrow the mouth), its walls scanned for 2.5 m, its end unscanned."""
    b = MapBuilder(14.0, 8.0, origin=(-1.0, -2.0))
    b.room(0.0, 0.0, 6.0, 4.0).room(6.1, 1.1, 8.6, 2.9)
    b.wall(6.05, 1.0, 6.05, 3.0).free(5.9, 1.4, 6.2, 2.6)
    b.unknown(8.6, 1.0, 8.8, 3.0)
    return b.build("corridor leaving a room")


def test_a_gap_onto_a_walled_way_on_is_no_door_onto_the_unexplored() -> None:
    """Seen from the room alone (the corridor's floor counted unseen), the gap still has walls
    bounding what lies beyond it on both sides: a corridor running on, not a door onto the
    unexplored (a fan through a door is bounded by unknown)."""
    grid = corridor_leaving_a_room()
    wall, free, seen, unknown = seen_masks(grid)
    _, c = grid.world_to_index(6.2, 2.0)
    seen[:, int(c):] = False
    assert outer_gaps(wall, free, seen, unknown, grid.resolution_m, DEFAULT_PARAMS) == []


def exit_at_a_corridors_end() -> OccupancyGrid:
    """A 1.5 m corridor, 8 m long, ending at the building's outer wall (x = 8.05, running on
    past it both ways) in a 1.2 m exit: nearly as wide as the corridor. The robot, at x = 5 in
    the corridor, saw out through the exit: the rays through it spread 4 m into the unscanned
    outside."""
    b = MapBuilder(16.0, 8.0, origin=(-1.0, -3.0))
    b.room(0.0, 0.0, 8.0, 1.5).wall(8.05, -2.5, 8.05, 4.0).door_v(8.05, 0.75, 1.2, depth_m=0.2)
    grid = b.build("exit at a corridor's end")
    cells = grid.cells.copy()
    rows, cols = np.mgrid[0:cells.shape[0], 0:cells.shape[1]]
    x = grid.origin_x_m + (cols + 0.5) * grid.resolution_m
    y = grid.origin_y_m + (rows + 0.5) * grid.resolution_m - 0.75
    through_exit = np.abs(y * (8.05 - 5.0) / np.maximum(x - 5.0, 1e-6)) <= 0.55
    cells[(x > 8.1) & (x < 12.0) & through_exit & (cells == UNKNOWN)] = FREE
    return OccupancyGrid(cells, grid.resolution_m, grid.origin_x_m, grid.origin_y_m, source=grid.source)


def test_an_exit_in_the_outer_wall_at_a_corridors_end_is_a_door() -> None:
    """The corridor runs on behind the exit as narrow as it (a passage's mouth, judged on its
    depth alone), but the exit is a gap in the outer wall's line, as deep as the wall: the one
    door, from the corridor to the unexplored outside."""
    grid = exit_at_a_corridors_end()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 4.0, 0.75)
    assert len(seg.doors) == 1
    door = door_near(seg.doors, 8.05, 0.75, tol=0.2)
    assert door.connects == (corridor.id, UNKNOWN_ID)
    assert door.width_m == pytest.approx(1.2, abs=POS_TOL_M)


def _line_scores_reference(rows: np.ndarray, neg_cols: np.ndarray, degs: np.ndarray) -> np.ndarray:
    """The wall-direction score written plainly: per direction and its right angle, the cells'
    line numbers ``rint(-col * sin + row * cos)``, and the sum of squared counts per line."""
    out = []
    for d in degs:
        t = math.radians(float(d))
        total = 0
        for c, s in ((math.cos(t), math.sin(t)), (-math.sin(t), math.cos(t))):
            x = neg_cols * s
            x += rows * c
            v = np.rint(x).astype(np.int64)
            counts = np.bincount(v - v.min())
            total += int((counts * counts).sum())
        out.append(total / rows.size)
    return np.array(out)


@pytest.mark.parametrize("seed", range(6))
def test_line_scores_equal_the_plain_rounding_of_every_cell(seed: int) -> None:
    """The fast score (rounding by adding a large constant) is bit for bit the plain one, on
    cell sets of every size (one direction per block to many), fine and coarse directions, and
    the directions whose projections fall exactly half-way between two lines (0, 30, 45, 60 deg)."""
    from langnav.analysis.wall_lines import _line_scores

    rng = np.random.default_rng(seed)
    n = int(rng.choice([2, 40, 700, 5000, 40_000]))
    side = int(rng.choice([8, 64, 900]))
    rows = rng.integers(0, side, n).astype(np.float64)
    cols = rng.integers(0, side, n).astype(np.float64)
    degs = np.concatenate([np.arange(0.0, 90.0, 7.5), rng.uniform(0.0, 90.0, 9), [30.0, 45.0, 60.0]])
    assert np.array_equal(_line_scores(rows, -cols, degs), _line_scores_reference(rows, -cols, degs))


def offices_behind_a_glass_front() -> OccupancyGrid:
    """A 2.2 m corridor, 22 m long, with three 6 m x 5 m offices along its north side behind a
    glass front the lidar saw only at its piers: 0.3 m pieces of wall every 2 m (1.7 m of
    glass between them), between the corridor's solid north wall at both ends."""
    b = MapBuilder(24.0, 10.0)
    b.room(0.5, 1.0, 22.5, 3.2)  # the corridor
    for x0 in (2.5, 8.65, 14.8):
        b.room(x0, 3.35, x0 + 6.0, 8.35)
    b.free(2.5, 3.2, 20.8, 3.35)  # the glass front, scanned only at the piers
    for i in range(10):
        b.wall(2.35 + 2.0 * i, 3.275, 2.65 + 2.0 * i, 3.275, 0.15)
    return b.build("offices behind a glass front")


def test_offices_behind_a_glass_front_between_piers_are_rooms_off_the_hallway() -> None:
    """No gap of the front is a door cut in solid wall (each has a pier at one end), and the
    corridor does not rise above them: by its clearance the corridor and the offices are one
    space. The front runs in the corridor's wall line, from solid wall to solid wall, broken
    into pieces no farther apart than an opening: a person sees a glass front, and three
    offices behind it."""
    grid = offices_behind_a_glass_front()
    seg = segment_spaces(grid)
    corridor = space_at(seg, grid, 11.5, 2.1)
    offices = [space_at(seg, grid, x, 6.0) for x in (5.5, 11.65, 17.8)]
    assert corridor.kind == ElementKind.HALLWAY
    assert [o.kind for o in offices] == [ElementKind.ROOM] * 3
    assert len({corridor.id, *(o.id for o in offices)}) == 4
    assert len(seg.rooms) == 4
    for office in offices:
        assert office.area_m2 == pytest.approx(6.0 * 5.0, rel=0.05)
        # The map cannot tell the front's door from its panes: each gap is a way in, and every
        # one lies in the front, none across the corridor or between two offices.
        ways = [d for d in seg.doors if set(d.connects) == {corridor.id, office.id}]
        assert len(ways) == 3
        assert all(abs(d.center[1] - 3.3) <= 0.1 for d in ways)
    assert len(seg.doors) == 9


def hall_with_a_row_of_posts() -> OccupancyGrid:
    """A 14 m x 10 m hall with a row of 0.1 m posts (a rope barrier, a row of bollards, a
    queue line) every 1.5 m across it from wall to wall, in line with the east wall of a
    cloakroom at the hall's north side."""
    b = MapBuilder(16.0, 16.0)
    b.room(1.0, 1.0, 15.0, 11.0)
    b.room(1.0, 11.0, 7.0, 14.0).door_h(4.0, 11.0, 0.9)  # the cloakroom, east wall at x = 7.075
    for i in range(6):
        y = 1.75 + 1.5 * i
        b.box(7.025, y - 0.05, 7.125, y + 0.05)
    return b.build("hall with a row of posts")


def test_a_row_of_posts_across_a_hall_is_no_front() -> None:
    """The posts stand in line with a wall and the row runs from wall to wall with gaps no
    wider than an opening, as a front's piers do; but they are specks, not pieces of wall: the
    hall is one room."""
    grid = hall_with_a_row_of_posts()
    seg = segment_spaces(grid)
    hall = space_at(seg, grid, 4.0, 6.0)
    assert space_at(seg, grid, 11.0, 6.0) is hall
    assert hall.kind == ElementKind.ROOM
    cloakroom = space_at(seg, grid, 4.0, 12.5)
    assert cloakroom.id != hall.id
    assert len(seg.rooms) == 2
    assert [set(d.connects) for d in seg.doors] == [{hall.id, cloakroom.id}]
