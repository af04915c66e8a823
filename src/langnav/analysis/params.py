"""Named analysis thresholds, in metres, so results do not change with the map's resolution."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class AnalysisParams:
    #: Robot radius (TurtleBot 4 / Create 3 are ~0.17 m). Gaps narrower than 2x this are not passable.
    robot_radius_m: float = 0.17
    #: Clearance every computed goal keeps from occupied and unknown cells (the bench's 0.15 m + margin).
    goal_clearance_m: float = 0.20
    #: Door openings are between these widths (a narrow interior door to a double door).
    door_min_width_m: float = 0.55
    door_max_width_m: float = 1.6
    #: ... and a door a person points at may be wider still when it is cut in a wall: a double
    #: door, an open office front or a shop's sliding doors are up to this wide (m). Openings
    #: between door_max_width_m and this are doors when door_judge finds them in a wall, else
    #: openings; the flood's saddles still use door_max_width_m.
    door_wide_max_width_m: float = 2.0
    #: A wall is at most this thick; door jambs are found within this depth.
    door_max_depth_m: float = 0.45
    #: Narrow passages: clear width between 2 x robot radius and this, longer than a door is deep.
    passage_max_width_m: float = 1.0
    passage_min_length_m: float = 0.6
    #: Rooms smaller than this (m2) are merged into a neighbour: closets and segmentation slivers.
    room_min_area_m2: float = 1.0
    #: A space whose length / width exceeds this and whose width is below hallway_max_width_m is a hallway.
    hallway_min_elongation: float = 3.0
    hallway_max_width_m: float = 3.0
    #: A space with two openings or more, many times longer than its typical width (twice the median clearance along its
    #: centre line, whatever a wide junction or an alcove adds at one point) is a corridor:
    #: length / typical width at least this (a room with a cupboard in a corner is not ten times
    #: longer than wide) ...
    hallway_long_elongation: float = 10.0
    #: A narrow space entered through one doorway only is a room (a store room, a long
    #: bathroom) unless it is at least this many times longer than wide: rooms rarely are, a
    #: dead-end corridor whose other doors are closed is.
    hallway_dead_end_min_elongation: float = 5.0
    #: ... and at most this share of its floor lies farther than hallway_max_width_m / 2 from
    #: every wall (a hall with wide open floor between its aisles is a room).
    hallway_max_wide_share: float = 0.2
    #: A room or hallway is wide enough for a person to walk and turn: a space whose widest point
    #: is narrower than this (m; building codes ask ~0.9 m of corridor) is a sliver (a laser-ray
    #: fan outside a wall, the gap behind a cabinet, a shelf's interior), not a space.
    space_min_width_m: float = 1.0
    #: Occupied clusters smaller than this are noise; larger ones apart from the walls are obstacles.
    obstacle_min_area_m2: float = 0.01
    #: Unknown regions smaller than this are noise specks, not unexplored areas (bench README).
    unexplored_min_area_m2: float = 0.05
    #: Segmentation: occupied specks up to this area (m2) touching free space are scan noise (floor).
    seg_speck_max_area_m2: float = 0.02
    #: Segmentation: unknown holes enclosed by free space up to this area (m2) are floor (unscanned
    #: spots behind furniture, sensor dropouts); larger enclosed ones still count in a room's area.
    seg_hole_max_area_m2: float = 0.5
    #: Segmentation: a space must be this much wider (clearance, m) than the doorway to it to be a
    #: space of its own rather than a bulge of its neighbour.
    seg_persistence_m: float = 0.15
    #: Segmentation: ... and its clearance peak must be at least this multiple of the doorway's.
    seg_peak_saddle_ratio: float = 1.0
    #: Segmentation: a connected piece of wall/unknown at least this big (m2) is the wall network
    #: (smaller free-standing pieces are furniture, see seg_island_max_area_m2, or wall stubs).
    seg_wall_network_min_area_m2: float = 2.0
    #: Segmentation: a smaller piece is a wall stub (a door jamb) when thin (<= 2 x door_max_depth_m)
    #: and at least this long (m); otherwise it is furniture, and gaps beside it are not doorways.
    seg_wall_min_length_m: float = 0.5
    #: Segmentation: wall and furniture pieces closer than this (m) count as one piece when
    #: telling door jambs from furniture (door frames scan as fragments).
    seg_jamb_join_m: float = 0.1
    #: Segmentation: free-standing clutter up to this area (m2: a table with its chairs, a
    #: cabinet) is segmented as floor, so that furniture does not split rooms.
    seg_island_max_area_m2: float = 2.0
    #: Segmentation: keep two spaces apart only where both jambs of the opening are walls.
    seg_jamb_test: bool = True
    #: Segmentation: two hallway-narrow spaces stay one corridor when their clearance peaks are
    #: below this multiple of the opening's (a corridor narrowed by a cabinet, not a door).
    seg_hallway_saddle_ratio: float = 1.6
    #: Segmentation: two spaces whose typical half-widths (twice their mean clearance: a
    #: corridor's half-width, whatever junctions and recesses raise its peak) are hallway-narrow,
    #: one of them elongated, stay one corridor when the opening is wider than about 2 / this of
    #: the corridor's width: the opening's clearance exceeds the wider half-width / this ratio
    #: (a corridor narrowed by cabinets or a pillar, not a door; 0 switches it off).
    seg_corridor_saddle_ratio: float = 1.8
    #: Segmentation: an opening between two spaces wider than a door, up to this width (m), still
    #: separates them when it is a gap in a wall line (0 switches it off); it is reported as a
    #: door (an opening) of that width.
    seg_wall_gap_max_width_m: float = 3.0
    #: Segmentation: ... a gap in a wall line: the wall runs on straight past both jambs for this
    #: length (m), non-floor on at least this share of it (scanned walls have holes).
    seg_wall_line_min_length_m: float = 1.0
    seg_wall_line_min_share: float = 0.8
    #: Segmentation: an unknown region enclosed by a room counts in its area up to this size (m2;
    #: an unscanned corner or half of a room), never a courtyard inside a corridor loop.
    seg_enclosed_unknown_max_area_m2: float = 30.0
    #: Segmentation: a space joins its neighbour when the opening between them is at least this
    #: multiple of the square root of its area (m / sqrt(m2); 0 switches it off).
    seg_merge_gap_ratio: float = 0.4
    #: Segmentation: grids with more cells than this (after cropping to the free space) are
    #: segmented at seg_coarse_resolution_m, to keep large maps fast (thresholds are in metres).
    seg_max_cells_full_resolution: int = 1_500_000
    seg_coarse_resolution_m: float = 0.1
    #: Segmentation: judge every door-wide opening between two spaces (any gap beside furniture
    #: joins them) instead of only the widest one.
    seg_jamb_all_openings: bool = False
    #: Segmentation: two spaces joined through more door-wide openings than this are one space
    #: (a row of desks or shelves, not a wall; 0 switches it off).
    seg_max_openings_between: int = 2
    #: Segmentation: unknown notches of a space narrower than twice this (m; the unscanned wedges
    #: between laser rays) count as part of it (0 switches it off).
    seg_close_unknown_gaps_m: float = 0.5
    #: Segmentation: free cells left out of every space (thin laser rays across an unscanned
    #: room) join the space they reach first through free cells within this distance (m; 0 off).
    seg_claim_free_m: float = 3.0
    #: Segmentation: clearance (m) below which a free cell cannot start a space (about a robot radius).
    seg_min_peak_m: float = 0.15
    # -- wall lines (langnav.analysis.wall_lines): door-wide gaps in the building's walls --
    #: Segmentation: a gap in a wall line from door_min_width_m up to this width (m: a double
    #: door, an open office front) parts the spaces on its two sides before the flood, with a
    #: doorway in it (0 switches it off). Wider openings are an open plan's arches, judged by
    #: the flood alone.
    seg_wall_line_gap_max_m: float = 2.0
    #: Segmentation: ... when the wall line runs on past both ends of the gap for this length
    #: (m: a wall, not a cabinet's corner), occupied on at least this share of it (a dashed
    #: line: glass, laser gaps, open door leaves).
    seg_wall_line_side_m: float = 1.0
    seg_wall_line_side_share: float = 0.5
    #: Segmentation: a gap in a wall line wider than seg_wall_line_gap_max_m, up to this width
    #: (m: the wide arch between a home's living room and its dining room or bedroom wing),
    #: parts the spaces on its two sides too when the wall runs on past each of its ends for at
    #: least half its width (a wall with an arch cut in it, not an open plan's short stubs);
    #: wider openings join the spaces (one open-plan floor). 0 switches it off.
    seg_wall_line_arch_max_m: float = 4.0
    # -- unexplored areas a person would send the robot to look at (not furniture insides) --
    #: An unknown region is worth a trip from this size (m2): a square about two robot widths
    #: across (0.7 m), room for the robot to drive in and turn; smaller pockets are the shadows
    #: of table legs and clutter (the bench README's 0.05 m2 specks are noise in any case).
    unexplored_worth_area_m2: float = 0.5
    #: ... and when the robot can come up to this much of its frontier in one opening (m of a
    #: connected run of frontier cells within a robot radius of where the robot fits): an opening
    #: it can look or drive through, as wide as the robot plus a margin (explore.py's smallest
    #: frontier worth a trip). Laser holes in a wall, and the gaps in the scanned outline of a
    #: shelf or a cabinet whose inside is unknown, are narrower. The outside world too, and an
    #: area's reported frontier is its runs this long (the robot reaches them from the floor it
    #: mapped, see analysis/unexplored.py).
    unexplored_min_frontier_m: float = 0.4
    #: ... and when it is wide enough for the robot to drive in and turn: it holds a disc this
    #: wide (m; two robot widths, the side of unexplored_worth_area_m2's square), counting the
    #: free laser rays across it that the robot does not fit in as part of it (a room seen through
    #: a fan of rays is one wide region). The unknown inside a shelf, a rack or a cabinet, and the
    #: slivers between a wall and the rays along it, are thinner however long they are.
    unexplored_min_width_m: float = 0.7
    #: ... and when it is not a thing the robot scanned all round: an unknown region with free
    #: floor on every side (touching no wall) narrower than this (m; twice the 3.5 m range of the
    #: shortest-ranged common robot lidar, a TurtleBot3's) would have been seen into from the
    #: floor around it had nothing stood in the way: a group of desks, a glass table, a plant.
    unexplored_enclosed_max_width_m: float = 7.0
    #: Straight wall segments shorter than this are not reported.
    wall_min_length_m: float = 0.5
    #: Maximum deviation of wall points from their fitted segment.
    wall_max_deviation_m: float = 0.1


DEFAULT_PARAMS = AnalysisParams()
