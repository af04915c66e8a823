"""Maps the analysis tests build, with their elements known exactly (world metres)."""

from __future__ import annotations

from langnav.maps.draw import MapBuilder
from langnav.maps.grid import OCCUPIED, OccupancyGrid


def room_with_door() -> OccupancyGrid:
    """A 4 x 3 m room, door 0.9 m wide in the east wall at y = 1.5 onto the unknown outside,
    a 0.5 x 0.4 m box, a 1 x 1 m unscanned patch in the north-west corner and a noise speck."""
    b = MapBuilder(6.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 4.0, 3.0)
    b.door_v(4.075, 1.5, 0.9)
    b.box(1.0, 1.0, 1.5, 1.4)
    b.unknown(0.0, 2.0, 1.0, 3.0)
    b.unknown(2.5, 0.5, 2.55, 0.55)  # one unknown cell: a speck, not an area
    return b.build(source="room_with_door")


def l_room() -> OccupancyGrid:
    """An L-shaped room: (0..4, 0..2) and (0..2, 2..4), closed, walls 0.15 m."""
    b = MapBuilder(6.0, 6.0, origin=(-1.0, -1.0))
    b.rect(-0.15, -0.15, 4.15, 2.15, OCCUPIED).rect(-0.15, -0.15, 2.15, 4.15, OCCUPIED)
    b.free(0.0, 0.0, 4.0, 2.0).free(0.0, 0.0, 2.0, 4.0)
    return b.build(source="l_room")


def corridor_with_side_passage() -> OccupancyGrid:
    """A 10 x 1.6 m corridor; from its middle a 0.7 m wide, 2 m long passage leads north into
    a 3 x 2.4 m room."""
    b = MapBuilder(12.0, 8.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 10.0, 1.6)
    b.room(3.5, 3.6, 6.5, 6.0)
    b.rect(4.3, 1.6, 5.7, 3.6, OCCUPIED)
    b.free(4.65, 1.5, 5.35, 3.7)
    return b.build(source="corridor_with_side_passage")


def two_rooms_partition() -> OccupancyGrid:
    """Two 3 x 3 m rooms side by side; the partition between them is a free-standing wall piece
    (doors at both of its ends), plus a 0.6 x 0.6 m box in the west room."""
    b = MapBuilder(8.0, 5.0, origin=(-1.0, -1.0))
    b.room(0.0, 0.0, 6.15, 3.0)
    b.wall(3.075, 0.0, 3.075, 3.0)
    b.door_v(3.075, 0.45, 0.9, depth_m=0.2).door_v(3.075, 2.55, 0.9, depth_m=0.2)
    b.box(1.0, 1.2, 1.6, 1.8)
    b.rect(5.0, 2.0, 5.05, 2.05, OCCUPIED)  # one occupied cell: noise, not an obstacle
    return b.build(source="two_rooms_partition")
