"""The blind12 buildings (building frame: u east, v north, metres). See README.md.
Routes are planned through listed stops with B.tour (blind8). Written from scratch for round 12."""
import math

from sim import B

EXT = 0.24


# ----------------------------------------------------------------------------------------------
def boatyard():
    b = B("b12_boatyard_shed", "Boat-builder's shed (36 x 22 m, rotated 33 deg, 0.1 m cells). A 24 x 22 m building "
          "shed (ONE room) with a yacht hull on its cradle (a solid block whose inside is never seen), a dinghy, a "
          "timber rack, benches (a 0.75 m gap between two free-standing benches = passage), a 1.0 m pedestrian door "
          "and an open 2.4 m slipway roller door (optional: wider than a door); an annex with a 1.8 m corridor "
          "(1.2 m double door from the shed, 1.0 m fire exit), joinery shop (1.6 m double door from the shed, 1.0 m "
          "from the corridor), spray-booth room (1.0 m), office (0.9 m), mess room (0.9 m), washroom (0.8 m, through "
          "the mess room), boat stores (1.2 m from the shed; racks: a 0.8 m aisle open at both ends = passage, a "
          "0.8 m slot closed by the east wall = dead end, not a passage). Hard: coarse 0.1 m cells, the hull, "
          "wide-open shed.", (36, 22), theta=33, seed=121, margin=7.0, res=0.1, pad=1.5)
    w = b.wall
    w((0, 0), (36, 0), EXT, doors=[(15.0, 1.0, "shed pedestrian door (to the yard)", ("a", 1, 85))])
    w((36, 0), (36, 22), EXT, doors=[(10.4, 1.0, "annex corridor east fire exit (to outside)", ("a", -1, 80))])
    w((36, 22), (0, 22), EXT, windows=[(25.0, 30.0)])
    w((0, 22), (0, 0), EXT, doors=[(6.0, 2.4, "slipway roller door, open (2.4 m, to the yard)", None, True)])
    w((24, 0), (24, 22), 0.2, doors=[(4.0, 1.6, "shed to joinery shop (double door)", ("d", -1, 80)),
                                     (10.4, 1.2, "shed to annex corridor (double door)", ("d", 1, 85)),
                                     (19.0, 1.2, "shed to boat stores", ("a", 1, 90))])
    w((24, 9.5), (36, 9.5), 0.15, doors=[(3.5, 1.0, "corridor to joinery shop", ("a", -1, 90)),
                                         (9.0, 1.0, "corridor to spray-booth room", ("b", -1, 90))])
    w((24, 11.3), (36, 11.3), 0.15, doors=[(2.5, 0.9, "corridor to office", ("a", 1, 90)),
                                           (8.5, 0.9, "corridor to mess room", ("b", 1, 90))])
    w((31, 0), (31, 9.5), 0.15)
    w((29, 11.3), (29, 16), 0.12)
    w((24, 16), (36, 16), 0.15, doors=[(10.5, 0.8, "mess room to washroom", ("a", 1, 90))])
    w((33, 16), (33, 22), 0.12)
    # shed
    b.poly([(5.0, 10.3), (5.0, 13.7), (13.0, 13.9), (17.0, 12.0), (13.0, 10.1)])       # yacht hull on its cradle
    b.rbox(5.5, 4.5, 4.2, 1.6, 12)                                                    # dinghy
    b.box(2.0, 20.9, 14.0, 21.86)                                                     # timber rack
    b.box(0.14, 2.0, 0.9, 8.0)                                                        # bench by the west wall
    b.box(14.0, 5.0, 17.0, 5.9); b.box(17.75, 5.0, 20.75, 5.9)                        # two free-standing benches
    b.passage(17.375, 5.45, 0.75, "shed: gap between two free-standing benches", across=(1, 0))
    b.table(18.0, 1.2, 22.0, 2.8, leg=0.14)                                           # boat trailer (wheels)
    b.clutter((1.0, 21.88), (23.5, 21.88), -1, 2, avoid=[(1.0, 13.5)])
    b.dot(21.0, 14.0, 0.3); b.dot(9.0, 17.5, 0.25)                                    # drums / a compressor
    # joinery
    b.box(25.8, 3.0, 27.4, 4.2); b.box(28.4, 1.6, 29.4, 3.8); b.box(24.2, 0.14, 30.8, 0.85)
    b.clutter((30.9, 9.4), (30.9, 0.2), 1, 2, depth=(0.4, 0.6), avoid=[(0.0, 1.0)])
    # spray-booth room: the booth itself is a closed box
    b.box(32.5, 1.0, 35.5, 5.5)
    # office / mess / washroom
    b.desk(24.2, 14.6, 26.0, 15.9, "n"); b.chair(25.1, 14.1)
    b.box(29.1, 15.3, 32.0, 15.9)
    b.table(31.0, 12.6, 33.0, 13.8); b.chair(30.6, 13.2); b.chair(33.4, 13.2)
    b.seg((34.0, 19.5), (35.88, 19.5), 0.05); b.seg((34.0, 19.5), (34.0, 21.88), 0.05)  # shower cubicle
    # stores: racks
    b.box(26.0, 17.4, 31.5, 18.0); b.box(26.0, 18.8, 32.93, 19.4); b.box(26.0, 20.2, 32.93, 20.8)
    b.passage(28.8, 18.4, 0.8, "boat stores: aisle between two racks", across=(0, 1))
    b.outside(14, dmin=1.5, dmax=6.0)
    b.person([(12.0, 16.0), (20.0, 17.0)], speed=0.12)
    b.person([(27.0, 6.0)], start=150, stop=900)
    b.person([(10.0, 8.0), (10.0, 3.0)], speed=0.1, start=400)
    b.space(19.5, 15.0, "room", "boat shed", region=(0.6, 0.6, 23.4, 21.4))
    b.space(27.5, 7.0, "room", "joinery shop", region=(24.5, 1.0, 30.5, 9.0))
    b.space(33.5, 7.5, "room", "spray-booth room", region=(31.5, 5.9, 35.5, 9.0))
    b.space(30.0, 10.4, "hallway", "annex corridor", region=(24.5, 9.7, 35.5, 11.1))
    b.space(26.5, 13.3, "room", "office", region=(24.4, 11.7, 28.6, 15.4))
    b.space(32.5, 14.2, "room", "mess room", region=(29.4, 11.7, 35.6, 15.6))
    b.space(34.5, 17.8, "room", "washroom", region=(33.4, 16.4, 35.6, 19.3))
    b.space(25.0, 20.0, "room", "boat stores", region=(24.4, 16.4, 25.9, 21.6))
    T = b.tour
    T([(15.0, 1.6), (21.0, 3.6), (22.0, 8.0), (17.375, 7.0), (17.375, 4.2), (10.0, 3.8), (2.0, 1.5), (2.0, 9.5),
       (3.0, 16.0), (1.0, 16.0), (8.0, 19.5), (18.0, 19.5), (18.0, 15.0), (22.0, 12.0), (22.5, 10.4), (27.5, 10.4),
       (27.5, 8.0), (27.0, 2.0), (25.0, 6.0), (27.5, 8.0), (27.5, 10.4), (33.0, 10.4), (33.0, 8.0), (34.0, 7.0),
       (33.0, 10.4), (35.0, 10.4), (32.5, 10.4), (32.5, 13.5), (34.5, 14.5), (34.5, 17.5), (34.5, 18.8),
       (34.5, 14.5), (32.5, 12.0), (26.5, 10.4), (26.5, 13.5), (25.0, 12.5), (26.5, 10.4), (23.0, 10.4),
       (22.0, 17.0), (23.0, 19.0), (25.0, 19.0), (25.0, 18.4), (32.3, 18.4), (32.3, 17.0), (25.0, 16.8),
       (25.0, 20.2), (23.0, 19.0), (19.0, 18.0), (10.0, 16.0), (5.0, 8.0), (15.0, 1.6)])
    T([(15.0, 1.6), (20.0, 9.0), (23.0, 10.4), (30.0, 10.4), (23.0, 10.4), (20.0, 16.0), (6.0, 17.0), (4.0, 6.0),
       (15.0, 1.6)], bias=(0.05, -0.06, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def music_school():
    b = B("b12_music_school", "Music school (30 x 16 m L-shaped, rotated -21 deg, 0.05 m cells; world frame at the "
          "robot's start pose in the lobby; 4 m unknown canvas). Lobby behind a GLASS front (1.8 m sliding double "
          "door), a 2 m corridor the length of the building (1.4 m double fire door from the lobby, 1.0 m east fire "
          "exit, a 1.5 x 1.5 m alcove with a water fountain) lined with PRACTICE CELLS (3 x 4 m, 0.8 m doors, thick "
          "walls; one cell's door is closed, so that cell is not annotated); recital hall (1.6 m double door from the "
          "lobby, 1.0 m from the corridor; stage riser, grand piano, chair rows), percussion room (1.2 m double "
          "door), library behind the north cells (0.9 m doors from the recital hall and the percussion room), "
          "a 10.5 x 7 m ensemble / teaching room (0.9 m door and 1.2 m double door from the corridor; desks at its "
          "west end) with an instrument store (0.8 m). No narrow passages.",
          (30, 16), theta=-21, seed=122, margin=7.0, res=0.05, start_frame=True, pad=4.0)
    b.foot = [(0, 0), (18, 0), (18, 3), (30, 3), (30, 16), (0, 16)]
    w = b.wall
    w((0, 0), (6, 0), EXT, glass=True, doors=[(3.0, 1.8, "lobby glass sliding double door (street)", ("s2", 1))])
    w((6, 0), (18, 0), EXT, windows=[(1.5, 4.5), (7.5, 10.5)])
    w((18, 0), (18, 3), EXT); w((18, 3), (30, 3), EXT)
    w((30, 3), (30, 16), EXT, doors=[(5.0, 1.0, "corridor east fire exit (to outside)", ("a", -1, 80))])
    w((30, 16), (0, 16), EXT)
    w((0, 16), (0, 0), EXT, windows=[(2.0, 5.0)])
    w((0, 9), (6, 9), 0.15, doors=[(3.0, 1.6, "lobby to recital hall (double door)", ("d", 1, 80))])
    w((6, 0), (6, 9), 0.15, doors=[(8.0, 1.4, "lobby to corridor (double fire door, held open)", ("d", -1, 85))])
    w((6, 7), (16.5, 7), 0.15, doors=[(3.0, 0.9, "corridor to ensemble / teaching room (west door)", ("a", -1, 90)),
                                      (8.0, 1.2, "corridor to ensemble / teaching room (double door)", ("d", -1, 85))])
    w((16.5, 0), (16.5, 7), 0.15, doors=[(2.5, 0.8, "ensemble / teaching room to instrument store", ("a", 1, 90))])
    w((16.5, 5.5), (18, 5.5), 0.15)
    w((18, 3), (18, 7), 0.15)
    w((18, 7), (30, 7), 0.15, doors=[(1.5, 0.8, "corridor to practice cell S1", ("a", -1, 95)),
                                     (4.5, 0.8, "corridor to practice cell S2", ("a", -1, 95)),
                                     (7.5, 0.8, "corridor to practice cell S3 (closed)", None, False, True),
                                     (10.5, 0.8, "corridor to practice cell S4", ("b", -1, 90))])
    for u in (21, 24, 27):
        w((u, 3), (u, 7), 0.2)
    w((6, 9), (30, 9), 0.15, doors=[(4.0, 1.0, "corridor to recital hall", ("a", 1, 90)),
                                    (7.5, 0.8, "corridor to practice cell N1", ("a", 1, 95)),
                                    (10.5, 0.8, "corridor to practice cell N2", ("a", 1, 95)),
                                    (13.5, 0.8, "corridor to practice cell N3", ("b", 1, 90)),
                                    (16.5, 0.8, "corridor to practice cell N4", ("a", 1, 95)),
                                    (21.0, 1.2, "corridor to percussion room (double door)", ("d", 1, 85))])
    w((12, 9), (12, 16), 0.2, doors=[(5.5, 0.9, "recital hall to library", ("a", -1, 90))])
    for u in (15, 18, 21):
        w((u, 9), (u, 13), 0.2)
    w((12, 13), (24, 13), 0.2)
    w((24, 9), (24, 16), 0.2, doors=[(5.5, 0.9, "percussion room to library", ("b", 1, 90))])
    # lobby
    b.box(0.14, 6.0, 2.0, 6.7)                                     # reception desk
    b.box(4.6, 0.4, 5.8, 0.9)                                      # bench
    # recital hall
    b.box(0.14, 13.5, 4.2, 15.88)                                  # stage riser
    b.rbox(6.0, 14.0, 2.0, 1.5, 0)                                 # grand piano
    for vv in (11.0, 12.2):
        for k in range(9):
            b.chair(5.5 + 0.6 * k, vv, 0)
    # cells: upright pianos against the back walls
    for u0 in (12, 15, 18, 21):
        b.box(u0 + 0.4, 12.3, u0 + 1.9, 12.88); b.chair(u0 + 1.1, 11.8, 0)
    for u0 in (18, 21, 27):
        b.box(u0 + 0.4, 3.13, u0 + 1.9, 3.7)
    b.box(24.4, 3.13, 25.9, 3.7)
    # library / percussion / office / ensemble / store
    b.box(12.6, 15.4, 23.4, 15.88)
    b.table(16.5, 13.6, 19.5, 14.6)
    b.dot(25.5, 14.5, 0.35); b.dot(26.5, 15.0, 0.35); b.box(27.5, 15.3, 29.8, 15.86)   # timpani, marimba
    for u, v in [(26.0, 11.5), (26.4, 11.0), (25.6, 10.9), (26.8, 11.6)]:
        b.dot(u, v, 0.12)                                          # drum kit
    b.desk(6.2, 5.8, 8.0, 6.9, "n"); b.desk(10.0, 0.2, 11.8, 1.2, "s"); b.chair(7.1, 5.3); b.chair(10.9, 1.7)
    for k in range(6):
        b.chair(12.8 + 0.6 * k, 4.5, 0); b.dot(12.8 + 0.6 * k, 5.1, 0.02)
    b.box(16.7, 0.14, 17.8, 0.7)                                   # instrument cases at the back of the store
    b.dot(17.25, 6.8, 0.15)                                        # water fountain in the alcove
    b.outside(10, dmin=1.5, dmax=4.0)
    b.person([(7.0, 8.0), (25.0, 8.0)], speed=0.12)
    b.person([(2.5, 4.0)], start=0, stop=700)
    b.person([(8.0, 10.3), (11.0, 10.3)], speed=0.05, start=200)
    b.space(3.5, 3.5, "room", "lobby", region=(0.6, 0.8, 5.4, 8.4))
    b.space(20.0, 8.0, "hallway", "corridor", region=(7.0, 7.5, 29.0, 8.5))
    b.space(8.5, 10.0, "room", "recital hall", region=(0.6, 9.6, 11.4, 15.4))
    # (the office and the ensemble room share one 10.5 x 7 m room: no wall between them)
    b.space(11.0, 3.5, "room", "ensemble / teaching room (desks at its west end)", region=(6.6, 1.5, 15.9, 6.4))
    b.space(17.25, 2.8, "room", "instrument store", region=(16.6, 0.6, 17.9, 5.0))
    for i, u0 in enumerate((12, 15, 18, 21)):
        b.space(u0 + 1.5, 10.6, "room", f"practice cell N{i + 1}", region=(u0 + 0.5, 9.5, u0 + 2.5, 11.6))
    for nm, u0 in (("S1", 18), ("S2", 21), ("S4", 27)):
        b.space(u0 + 1.5, 5.3, "room", f"practice cell {nm}", region=(u0 + 0.5, 4.2, u0 + 2.5, 6.5))
    b.space(27.0, 12.5, "room", "percussion room", region=(24.6, 9.6, 29.4, 14.8))
    b.space(14.5, 14.3, "room", "library", region=(12.6, 13.5, 23.4, 15.0))
    T = b.tour
    T([(3.0, 1.6), (4.5, 4.0), (1.2, 8.0), (3.0, 10.5), (1.5, 12.8), (11.0, 12.85), (11.0, 10.0), (10.0, 9.9),
       (10.0, 8.0), (9.0, 8.0), (9.0, 5.0), (7.0, 2.0), (11.0, 2.2), (9.0, 5.0), (9.0, 8.0), (14.0, 8.0),
       (14.0, 5.5), (13.0, 1.5), (15.6, 1.5), (15.6, 2.5), (17.25, 2.5), (17.25, 4.8), (17.25, 2.5), (15.6, 2.5),
       (14.0, 5.5), (14.0, 8.0), (17.25, 8.0), (17.25, 6.3), (19.5, 8.0), (19.5, 5.0), (19.5, 8.0), (22.5, 8.0),
       (22.5, 5.0), (22.5, 8.0), (28.5, 8.0), (28.5, 5.0), (28.5, 8.0), (29.5, 8.0), (27.0, 8.0), (27.0, 12.5),
       (26.0, 14.5), (23.5, 14.5), (13.0, 14.5), (11.5, 14.5), (9.0, 15.2), (11.5, 14.5), (13.0, 14.5),
       (23.5, 14.5), (27.0, 12.5), (27.0, 8.0), (13.5, 8.0), (13.5, 11.0), (13.5, 8.0), (16.5, 8.0), (16.5, 11.0),
       (16.5, 8.0), (19.5, 8.0), (19.5, 11.0), (19.5, 8.0), (22.5, 8.0), (22.5, 11.0), (22.5, 8.0), (6.5, 8.0),
       (3.0, 6.0), (3.0, 1.6)])
    T([(3.0, 1.6), (5.0, 8.0), (25.0, 8.0), (5.0, 8.0), (3.0, 10.5), (9.0, 10.3), (3.0, 10.5), (3.0, 1.6)],
      bias=(-0.05, 0.06, -0.5))
    return b


# ----------------------------------------------------------------------------------------------
def dental_lab():
    b = B("b12_dental_lab", "Dental laboratory (16 x 11 m, rotated 141 deg, 0.025 m cells, front-facing 270 deg lidar with 480 beams; "
          "0.5 m border). Reception / dispatch behind a GLASS front (1.0 m glass street door); a 1.0 m SLIDING door "
          "(leaf parked beside the opening) into the main lab: wall benches and island benches (a 0.8 m gap between "
          "two islands and a 0.8 m strip between an island and the north wall bench = passages; a 0.7 m slot between "
          "two cabinets closed by the east wall = dead end, not a passage); a 1.2 m double door to an 11 m corridor "
          "(1.4 m clear; one hallway) with the ceramics room (0.9 m), CAD / milling room (0.8 m) and WC (0.7 m); "
          "plaster room (0.8 m from reception, 0.8 m to the corridor). Hard: 270 deg lidar, fine cells, benches "
          "everywhere.", (16, 11), theta=141, seed=123, margin=6.0, res=0.025, fov=270.0, pad=0.5, nbeams=480, scan_step=0.2)
    w = b.wall
    w((0, 0), (5, 0), EXT, glass=True, doors=[(2.5, 1.0, "reception glass street door (to outside)", None)])
    w((5, 0), (16, 0), EXT)
    w((16, 0), (16, 11), EXT, windows=[(1.0, 2.5)])
    w((16, 11), (0, 11), EXT)
    w((0, 11), (0, 0), EXT)
    w((0, 4.5), (5, 4.5), 0.12, doors=[(2.5, 0.8, "reception to plaster room", ("a", 1, 90))])
    w((5, 0), (5, 11), 0.12, doors=[(2.5, 1.0, "reception to main lab (sliding door)", ("s", 1)),
                                    (7.75, 0.8, "plaster room to corridor", ("b", -1, 90))])
    w((5, 7), (16, 7), 0.12, doors=[(3.0, 1.2, "main lab to corridor (double door)", ("d", -1, 85))])
    w((5, 8.5), (16, 8.5), 0.12, doors=[(2.5, 0.9, "corridor to ceramics room", ("a", 1, 90)),
                                        (6.75, 0.8, "corridor to CAD / milling room", ("a", 1, 90)),
                                        (9.75, 0.7, "corridor to WC", ("b", 1, 90))])
    w((10, 8.5), (10, 11), 0.12); w((13.5, 8.5), (13.5, 11), 0.12)
    # main lab
    b.box(5.2, 0.12, 15.88, 0.8)                                   # bench along the south wall
    b.box(7.0, 2.4, 10.0, 3.4); b.box(10.8, 2.4, 14.0, 3.4)         # island benches
    b.passage(10.4, 2.9, 0.8, "main lab: gap between two island benches", across=(1, 0))
    b.box(7.0, 4.6, 12.5, 5.6)                                     # third island
    b.box(10.0, 6.4, 15.88, 6.94)                                  # bench along the north wall
    b.passage(11.25, 6.0, 0.8, "main lab: strip between an island and the north wall bench", across=(0, 1))
    b.box(14.6, 3.6, 15.88, 4.2); b.box(14.6, 4.9, 15.88, 5.5)     # cabinets: dead-end 0.7 m slot
    for u in (7.6, 8.8, 11.4, 12.6):
        b.chair(u, 1.4, 0)
    for u in (8.0, 9.5, 11.0):
        b.chair(u, 4.0, 10)
    # reception / plaster room
    b.box(0.14, 2.6, 1.4, 3.6)
    b.box(0.14, 5.5, 0.8, 10.0); b.dot(1.5, 10.3, 0.25); b.box(3.8, 10.2, 4.9, 10.88)
    # ceramics / CAD / WC
    b.box(5.2, 10.2, 6.6, 10.88); b.box(8.4, 10.3, 9.88, 10.88)
    b.box(10.2, 10.1, 11.4, 10.88); b.desk(12.0, 10.2, 13.38, 10.88, "n")
    b.box(15.2, 10.2, 15.88, 10.88)
    b.outside(8, dmin=1.0, dmax=4.0)
    b.person([(6.0, 1.6), (14.0, 1.6)], speed=0.06)
    b.person([(12.0, 4.0)], start=100, stop=600)
    b.space(3.0, 1.8, "room", "reception / dispatch", region=(1.5, 0.6, 4.4, 4.0))
    b.space(8.0, 1.6, "room", "main lab", region=(5.6, 0.9, 15.4, 6.3))
    b.space(2.6, 8.0, "room", "plaster room", region=(1.0, 5.0, 4.4, 10.4))
    b.space(12.0, 7.75, "hallway", "corridor", region=(6.0, 7.3, 15.5, 8.2))
    b.space(7.5, 9.6, "room", "ceramics room", region=(5.6, 9.0, 9.4, 10.1))
    b.space(11.75, 9.5, "room", "CAD / milling room", region=(10.6, 9.0, 13.0, 10.0))
    b.space(14.75, 9.6, "room", "WC", region=(14.1, 9.1, 15.3, 10.0))
    T = b.tour
    T([(2.5, 1.2), (3.5, 3.5), (1.8, 1.5), (4.2, 2.5), (6.0, 1.6), (14.0, 1.6), (15.0, 3.0), (13.5, 4.2),
       (10.4, 4.0), (10.4, 1.6), (6.2, 1.6), (6.2, 4.0), (6.2, 6.0), (9.5, 6.0), (13.0, 6.0), (14.0, 6.0),
       (13.5, 4.2), (8.0, 6.1), (8.0, 7.75), (5.6, 7.75), (4.2, 7.75), (2.5, 6.0), (2.8, 9.8), (2.5, 5.2),
       (2.5, 6.5), (4.2, 7.75), (7.5, 7.75), (7.5, 9.7), (7.5, 7.75), (11.75, 7.75), (11.75, 9.6), (11.75, 7.75),
       (14.75, 7.75), (14.75, 9.6), (14.75, 7.75), (15.5, 7.75), (8.0, 7.75), (8.0, 6.1), (6.0, 4.0), (4.2, 2.5),
       (2.5, 1.2)])
    T([(2.5, 1.2), (6.0, 2.5), (12.0, 1.6), (8.0, 6.1), (8.0, 7.75), (15.0, 7.75), (8.0, 7.75), (8.0, 6.1),
       (4.2, 2.5), (2.5, 1.2)], bias=(0.04, 0.05, 0.45))
    return b


# ----------------------------------------------------------------------------------------------
def marina():
    b = B("b12_marina", "Marina office with pontoon sheds (20 x 18 m site, rotated 62 deg, 0.05 m cells; world frame at "
          "the robot's start pose in the lobby; PARTLY EXPLORED). Harbour office: lobby (1.2 m double street door, "
          "GLASS front to the pontoons with a 1.0 m glass door), 1.8 m corridor (1.2 m door from the lobby, 1.0 m "
          "door to the quay at its east end), chandlery (1.6 m opening; a 0.8 m aisle between a gondola and the "
          "wall shelving = passage), harbour master's office (0.9 m), showers (0.9 m; cubicle partitions), drying "
          "room (0.8 m), WC (0.8 m), a members' lounge behind a half-open 0.9 m door and a store behind a closed "
          "door. A detached row of four pontoon sheds (1.8 m double doors; the fourth closed) across the quay. "
          "The robot drove only the west two thirds of the corridor and went into sheds 1 and 2 only; the lounge, "
          "WC, shed 3 were seen from their doors at most (the checker kept / dropped them by what the map shows).",
          (20, 18), theta=62, seed=124, margin=6.0, res=0.05, start_frame=True, pad=2.0)
    b.set_footprint([(0, 0), (20, 0), (20, 9), (0, 9)], [(2, 13), (18, 13), (18, 18), (2, 18)])
    w = b.wall
    w((0, 0), (20, 0), EXT, doors=[(3.0, 1.2, "lobby street double door (to the car park)", ("d", 1, 80))])
    w((20, 0), (20, 9), EXT, doors=[(4.4, 1.0, "corridor east door (to the quay)", ("a", 1, 85))])
    w((20, 9), (6, 9), EXT, windows=[(1.0, 3.0)])
    w((6, 9), (0, 9), EXT, glass=True, doors=[(3.0, 1.0, "lobby glass door to the pontoons (to outside)", None)])
    w((0, 9), (0, 0), EXT)
    w((6, 0), (6, 9), 0.15, doors=[(4.4, 1.2, "lobby to corridor", ("a", -1, 90))])
    w((6, 3.5), (20, 3.5), 0.15, doors=[(2.5, 0.9, "corridor to showers", ("a", -1, 90)),
                                        (7.0, 0.8, "corridor to drying room", ("a", -1, 90)),
                                        (10.0, 0.8, "corridor to WC", ("b", -1, 90)),
                                        (12.5, 0.8, "corridor to store (closed)", None, False, True)])
    w((6, 5.3), (20, 5.3), 0.15, doors=[(3.5, 1.6, "corridor to chandlery (opening)", None),
                                        (8.5, 0.9, "corridor to harbour master's office", ("a", 1, 90)),
                                        (12.0, 0.9, "corridor to members' lounge (half-open door)", ("b", 1, 35))])
    for u in (11, 15, 17):
        w((u, 0), (u, 3.5), 0.12)
    for u in (13, 16):
        w((u, 5.3), (u, 9), 0.12)
    # pontoon sheds
    w((2, 13), (18, 13), 0.2, doors=[(2.0, 1.8, "pontoon shed 1 double door (to the quay)", ("d", -1, 100)),
                                     (6.0, 1.8, "pontoon shed 2 double door (to the quay)", ("d", -1, 100)),
                                     (10.0, 1.8, "pontoon shed 3 double door (to the quay)", ("d", -1, 100)),
                                     (14.0, 1.8, "pontoon shed 4 (closed)", None, False, True)])
    w((18, 13), (18, 18), 0.2); w((18, 18), (2, 18), 0.2); w((2, 18), (2, 13), 0.2)
    for u in (6, 10, 14):
        w((u, 13), (u, 18), 0.12)
    for u0 in (2, 6, 10, 14):
        b.box(u0 + 0.3, 16.6, u0 + 3.7, 17.88)                     # kayak / dinghy racks
        b.dot(u0 + 3.2, 14.0, 0.2)                                 # outboard motor stand
    # lobby
    b.box(0.14, 4.5, 1.0, 7.0)                                     # counter
    b.box(4.0, 0.4, 5.5, 0.9)
    # chandlery: gondola + wall shelving (0.8 m aisle)
    b.box(7.2, 6.9, 11.8, 7.5); b.box(6.1, 8.3, 12.9, 8.88)
    b.passage(9.5, 7.9, 0.8, "chandlery: aisle between the gondola and the wall shelving", across=(0, 1))
    # harbour master / lounge
    b.desk(14.0, 7.6, 15.8, 8.88, "n"); b.chair(14.9, 7.1); b.box(13.1, 5.4, 13.6, 6.6)
    b.box(16.6, 8.0, 19.0, 8.8); b.box(19.0, 6.0, 19.8, 8.8)        # lounge sofas
    # showers: cubicle partitions
    for u in (7.2, 8.4, 9.6):
        b.seg((u, 0.12), (u, 1.4), 0.04)
    b.box(6.2, 2.6, 6.6, 3.3)
    b.box(11.1, 0.12, 14.9, 0.6); b.box(14.3, 1.0, 14.9, 3.0)       # drying racks
    b.box(16.3, 0.12, 16.9, 0.8)
    b.dot(0.8, 11.5, 0.15); b.dot(19.0, 11.8, 0.15); b.dot(12.5, 11.6, 0.15)   # bollards on the quay
    b.outside(10, dmin=1.5, dmax=5.0)
    b.person([(2.0, 2.0), (4.5, 6.5)], speed=0.05)
    b.person([(8.0, 10.5), (1.0, 10.5)], speed=0.1, start=300)
    b.space(3.5, 3.0, "room", "lobby", region=(1.5, 0.6, 5.4, 8.4))
    b.space(10.5, 4.4, "hallway", "corridor", region=(7.0, 4.0, 19.0, 4.8))
    b.space(9.5, 6.2, "room", "chandlery", region=(6.6, 5.8, 12.4, 6.6))
    b.space(14.5, 6.6, "room", "harbour master's office", region=(13.7, 5.8, 15.4, 7.2))
    b.space(17.5, 6.5, "room", "members' lounge", region=(16.6, 5.8, 18.4, 7.6))
    b.space(8.5, 2.3, "room", "showers", region=(6.6, 1.7, 10.4, 3.0))
    b.space(12.8, 2.0, "room", "drying room", region=(11.6, 1.0, 13.9, 3.0))
    b.space(16.0, 2.0, "room", "WC", region=(15.5, 1.2, 16.5, 3.0))
    for i, u0 in enumerate((2, 6, 10)):
        b.space(u0 + 1.8, 15.0, "room", f"pontoon shed {i + 1}", region=(u0 + 0.6, 13.6, u0 + 3.4, 16.0))
    T = b.tour
    T([(3.0, 1.5), (1.5, 3.0), (4.5, 7.5), (3.0, 8.2), (3.0, 10.0), (5.0, 11.2), (4.0, 11.8), (4.0, 15.0),
       (3.0, 16.0), (4.0, 15.0), (4.0, 11.8), (8.0, 11.8), (8.0, 15.0), (8.0, 11.8), (5.0, 11.2), (3.0, 10.0),
       (3.0, 8.0), (5.2, 4.4), (8.5, 4.4), (8.5, 2.4), (7.0, 2.0), (10.2, 2.0), (8.5, 2.6), (8.5, 4.4),
       (9.5, 4.4), (9.5, 6.2), (6.6, 7.9), (12.4, 7.9), (12.4, 6.2), (9.5, 6.2), (9.5, 4.4), (13.0, 4.4),
       (13.0, 2.0), (13.0, 4.4), (14.5, 4.4), (14.5, 6.6), (14.5, 4.4), (5.2, 4.4), (3.0, 1.5)])
    T([(3.0, 1.5), (3.0, 8.0), (3.0, 10.0), (6.0, 11.5), (3.0, 10.0), (3.0, 8.0), (5.2, 4.4), (13.0, 4.4),
       (5.2, 4.4), (3.0, 1.5)], bias=(-0.06, -0.04, 0.55))
    return b


# ----------------------------------------------------------------------------------------------
def farm_shop():
    b = B("b12_farm_shop", "Farm shop with cold rooms (24 x 16 m, rotated 77 deg, 0.05 m cells, 360-beam lidar). Shop floor behind a "
          "GLASS front (2.0 m sliding double door) with gondolas (a 0.9 m aisle between two gondolas = passage), veg "
          "tables, a till, two chest freezers against the north wall with a 0.7 m slot between them (dead end, not "
          "a passage); cold rooms behind it: walk-in chiller (1.2 m SLIDING insulated door) and freezer (0.9 m "
          "sliding door, through the chiller), prep room (1.0 m double swing door) with a staff room (0.8 m, "
          "through the prep room); farm cafe (1.8 m opening from the shop, 1.0 m terrace door, WC 0.8 m); goods-in "
          "(1.2 m staff door; an open 2.5 m roller door to the yard, optional; pallet racks with a 0.8 m aisle open "
          "at both ends = passage).", (24, 16), theta=77, seed=125, margin=6.0, res=0.05, pad=1.0, nbeams=360, scan_step=0.2)
    w = b.wall
    w((0, 0), (16, 0), EXT, glass=True, doors=[(8.0, 2.0, "shop sliding double glass door (to the car park)", ("s2", 1))])
    w((16, 0), (24, 0), EXT, doors=[(2.5, 1.0, "cafe door (to the terrace)", ("a", 1, 90))], windows=[(4.0, 6.5)])
    w((24, 0), (24, 16), EXT, doors=[(11.0, 2.5, "goods-in roller door, open (2.5 m, to the yard)", None, True)])
    w((24, 16), (0, 16), EXT)
    w((0, 16), (0, 0), EXT, windows=[(6.0, 10.0)])
    w((0, 11), (16, 11), 0.15, doors=[(2.0, 1.2, "shop to walk-in chiller (sliding insulated door)", ("s", -1)),
                                      (9.5, 1.0, "shop to prep room (double swing door)", ("d", 1, 80))])
    w((4, 11), (4, 16), 0.15, doors=[(2.5, 0.9, "chiller to freezer (sliding door)", ("s", -1))])
    w((7, 11), (7, 16), 0.15)
    w((12, 11), (12, 16), 0.12, doors=[(3.0, 0.8, "prep room to staff room", ("a", -1, 90))])
    w((16, 0), (16, 16), 0.2, doors=[(3.0, 1.8, "shop to cafe (wide opening)", None),
                                     (9.0, 1.2, "shop to goods-in (staff door)", ("a", -1, 90))])
    w((16, 6), (24, 6), 0.15)
    w((21.5, 3.5), (24, 3.5), 0.12)
    w((21.5, 3.5), (21.5, 6), 0.12, doors=[(1.25, 0.8, "cafe to WC", ("a", -1, 90))])
    # shop
    b.box(3.0, 3.0, 3.9, 8.5); b.box(4.8, 3.0, 5.7, 8.5)            # gondolas
    b.passage(4.35, 5.75, 0.9, "shop: aisle between two gondolas", across=(1, 0))
    b.box(8.5, 3.0, 9.4, 8.5)
    b.table(11.0, 3.0, 13.5, 4.5, leg=0.06); b.table(11.0, 6.0, 13.5, 7.5, leg=0.06)   # veg tables
    b.box(12.0, 10.2, 14.0, 10.92); b.box(14.7, 10.2, 15.9, 10.92)  # chest freezers (dead-end 0.7 m slot)
    b.box(9.8, 0.9, 11.6, 1.6)                                     # till
    b.clutter((0.12, 10.9), (0.12, 0.4), -1, 2, depth=(0.4, 0.5), avoid=[(0.0, 1.2), (4.4, 10.5)])
    # cold rooms / prep / staff
    b.box(0.12, 11.5, 0.7, 15.88); b.box(0.7, 15.3, 3.92, 15.88)
    b.box(6.3, 11.5, 6.92, 15.88)
    b.box(7.1, 15.2, 11.9, 15.88); b.box(8.5, 12.8, 10.5, 13.6)
    b.table(13.4, 12.4, 14.8, 13.4); b.chair(13.0, 12.9); b.chair(15.2, 12.9); b.box(12.1, 15.3, 15.88, 15.88)
    # cafe / WC
    for u, v in ((21.0, 1.6), (19.2, 4.8)):
        b.table(u - 0.4, v - 0.4, u + 0.4, v + 0.4); b.chair(u - 0.7, v); b.chair(u + 0.7, v)
    b.box(16.2, 5.2, 18.0, 5.88)
    b.box(23.3, 3.6, 23.88, 4.4)
    # goods-in: pallet racks + pallets
    b.box(17.5, 13.0, 22.6, 13.9); b.box(17.5, 14.7, 22.6, 15.6)
    b.passage(20.0, 14.3, 0.8, "goods-in: aisle between two pallet racks", across=(0, 1))
    b.box(19.0, 8.0, 20.2, 9.2); b.box(21.6, 6.3, 22.8, 7.5)
    b.outside(14, dmin=1.5, dmax=6.0)
    b.person([(7.0, 2.0), (7.0, 9.0)], speed=0.08)
    b.person([(12.5, 5.2)], start=0, stop=800)
    b.person([(18.0, 10.0), (22.0, 10.5)], speed=0.07, start=500)
    b.space(6.5, 9.8, "room", "shop floor", region=(0.6, 0.6, 15.4, 10.4))
    b.space(2.2, 13.3, "room", "walk-in chiller", region=(1.0, 11.6, 3.5, 15.0))
    b.space(5.3, 12.4, "room", "freezer", region=(4.6, 11.6, 6.0, 15.0))
    b.space(9.5, 14.4, "room", "prep room", region=(7.6, 11.6, 11.4, 15.0))
    b.space(14.0, 14.3, "room", "staff room", region=(12.6, 11.6, 15.4, 15.0))
    b.space(18.3, 2.6, "room", "farm cafe", region=(16.6, 0.6, 21.0, 5.0))
    b.space(22.8, 4.75, "room", "cafe WC", region=(22.2, 4.1, 23.3, 5.4))
    b.space(20.0, 10.8, "room", "goods-in", region=(16.6, 6.6, 23.4, 12.4))
    T = b.tour
    T([(8.0, 1.2), (6.8, 2.2), (1.2, 2.0), (1.5, 9.5), (4.35, 9.5), (4.35, 2.2), (7.0, 5.5), (10.5, 8.5),
       (14.5, 8.2), (15.0, 6.0), (15.0, 2.5), (17.0, 3.0), (18.5, 2.6), (23.0, 1.5), (20.6, 4.75), (22.8, 4.75),
       (20.6, 4.75), (17.0, 3.0), (15.0, 3.0), (15.0, 9.0), (16.8, 9.0), (18.0, 11.0), (16.8, 12.5), (16.8, 14.3),
       (23.2, 14.3), (23.2, 12.5), (23.0, 8.0), (23.5, 11.0), (18.0, 7.5), (16.8, 9.0), (15.0, 9.0), (9.5, 10.2),
       (9.5, 12.0), (9.5, 14.4), (11.4, 14.0), (13.0, 14.0), (14.5, 14.3), (13.0, 14.0), (11.4, 14.0), (8.0, 14.3),
       (9.5, 12.0), (9.5, 10.2), (2.0, 10.2), (2.0, 12.5), (3.0, 13.5), (5.3, 13.5), (5.3, 12.2), (5.3, 13.5),
       (2.2, 13.5), (2.0, 10.2), (8.0, 1.2)])
    T([(8.0, 1.2), (7.0, 6.0), (15.0, 9.0), (20.0, 10.0), (15.0, 9.0), (2.0, 10.0), (8.0, 1.2)],
      bias=(0.05, 0.05, -0.45))
    return b


# ----------------------------------------------------------------------------------------------
def coworking():
    b = B("b12_coworking", "Coworking floor (31 x 20 m, rotated -127 deg, 0.05 m cells, 360-beam lidar). Lobby behind a GLASS front "
          "(1.8 m sliding double door) with a 1.4 m glass door in a glass partition into a 20 x 14 m WORK HALL (one "
          "room: desk clusters, a long bench, sofas with a 0.7 m gap between them = passage, phone booths = closed "
          "boxes, two lockers with a 0.7 m slot closed by the north wall = dead end, not a passage) whose kitchen "
          "end has no wall (kitchen and hall share a group); two GLASS meeting pods in the hall (0.9 m glass doors); "
          "quiet room (0.9 m), toilets (0.9 m); a 1.6 m double door to a 2 m corridor with a 1.5 x 1.5 m alcove and "
          "a 2.5 m wide T junction with a cross corridor (one hallway; 1.4 m exit double door, 1.0 m east fire "
          "exit); meeting rooms 1-3 (0.9 / 0.9 glass / 1.0 m), offices 1-2 (0.8 / 0.9 m), print room (0.9 m from "
          "the cross corridor).", (31, 20), theta=-127, seed=126, margin=6.0, res=0.05, pad=0.75, nbeams=360, scan_step=0.2)
    w = b.wall
    w((0, 0), (12, 0), EXT, glass=True, doors=[(2.5, 1.8, "lobby sliding double glass door (street)", ("s2", 1))])
    w((12, 0), (31, 0), EXT, doors=[(17.75, 1.4, "cross-corridor exit double door (to outside)", ("d", -1, 80))])
    w((31, 0), (31, 20), EXT, doors=[(10.0, 1.0, "corridor east fire exit (to outside)", ("a", -1, 80))])
    w((31, 20), (0, 20), EXT, windows=[(2.0, 8.0), (13.0, 18.0)])
    w((0, 20), (0, 0), EXT, windows=[(5.0, 10.0)])
    w((5, 0), (5, 6), 0.15)
    w((0, 6), (5, 6), 0.1, glass=True, doors=[(2.5, 1.4, "lobby to work hall (glass door)", None)])
    w((12, 6), (20, 6), 0.15, doors=[(2.0, 0.9, "work hall to quiet room", ("a", -1, 90)),
                                     (6.0, 0.9, "work hall to toilets", ("b", -1, 90))])
    w((12, 0), (12, 6), 0.15); w((16, 0), (16, 6), 0.15)
    w((20, 0), (20, 9), 0.15)
    w((20, 9), (20, 20), 0.15, doors=[(1.0, 1.6, "work hall to corridor (double door)", ("d", -1, 85))])
    w((20, 9), (22, 9), 0.15, doors=[(1.0, 0.8, "corridor to office 1", ("a", -1, 90))])
    w((23.5, 9), (28.5, 9), 0.15, doors=[(3.0, 0.9, "corridor to office 2", ("a", -1, 90))])
    w((22, 7.5), (22, 9), 0.12); w((22, 7.5), (23.5, 7.5), 0.12); w((23.5, 7.5), (23.5, 9), 0.12)   # alcove
    w((20, 11), (23.5, 11), 0.15, doors=[(1.75, 0.9, "corridor to meeting room 1", ("a", 1, 90))])
    w((23.5, 11), (27, 11), 0.1, glass=True, mullion=1.0,
      doors=[(1.75, 0.9, "corridor to meeting room 2 (glass door)", None)])
    w((27, 11), (31, 11), 0.15, doors=[(2.0, 1.0, "corridor to meeting room 3", ("b", 1, 90))])
    w((23.5, 11), (23.5, 20), 0.12); w((27, 11), (27, 20), 0.12)
    w((20, 4), (28.5, 4), 0.15); w((24.25, 4), (24.25, 9), 0.12)
    w((28.5, 0), (28.5, 9), 0.15, doors=[(2.0, 0.9, "cross corridor to print room", ("a", 1, 90))])
    # glass meeting pods in the hall
    w((0, 15.5), (3.5, 15.5), 0.1, glass=True, mullion=1.0,
      doors=[(1.75, 0.9, "work hall to meeting pod A (glass door)", None)])
    w((3.5, 15.5), (7, 15.5), 0.1, glass=True, mullion=1.0,
      doors=[(1.75, 0.9, "work hall to meeting pod B (glass door)", None)])
    w((3.5, 15.5), (3.5, 20), 0.1, glass=True, mullion=1.0); w((7, 15.5), (7, 20), 0.1, glass=True, mullion=1.0)
    b.table(1.0, 17.5, 2.5, 18.7); b.table(4.5, 17.5, 6.0, 18.7)
    # hall furniture
    for u0, v0 in ((2.5, 8.5), (2.5, 11.5), (7.0, 8.5), (7.0, 11.5)):
        b.table(u0, v0, u0 + 2.5, v0 + 1.5)
        for k in (0.6, 1.9):
            b.chair(u0 + k, v0 - 0.45); b.chair(u0 + k, v0 + 1.95)
    b.table(11.0, 13.0, 17.0, 14.2)
    for k in range(5):
        b.chair(11.6 + 1.2 * k, 12.5, 0); b.chair(11.6 + 1.2 * k, 14.7, 0)
    b.box(11.0, 9.0, 13.0, 9.9); b.box(13.7, 9.0, 15.7, 9.9)       # sofas
    b.passage(13.35, 9.45, 0.7, "work hall: gap between two sofas", across=(1, 0))
    b.box(10.0, 18.9, 11.2, 19.88); b.box(11.3, 18.9, 12.5, 19.88)  # phone booths (closed boxes)
    b.box(17.0, 17.0, 17.6, 19.88); b.box(18.3, 17.0, 18.9, 19.88)  # lockers: dead-end 0.7 m slot
    b.dot(9.5, 15.0, 0.3); b.dot(19.2, 7.0, 0.3)                   # planters
    # kitchen / lobby / quiet room / toilets
    b.box(5.15, 0.14, 11.88, 0.8); b.box(7.0, 2.6, 10.0, 3.4)
    b.box(0.14, 3.0, 1.6, 3.8)
    b.box(12.2, 0.2, 13.2, 1.0); b.box(14.8, 0.2, 15.8, 1.0)
    for u in (17.3, 18.6):
        b.seg((u, 0.12), (u, 1.6), 0.04)
    b.box(19.3, 2.5, 19.9, 4.5)
    # east block
    b.desk(20.2, 4.2, 22.0, 5.0, "s"); b.desk(26.6, 4.2, 28.38, 5.0, "s")
    b.box(20.2, 0.2, 22.5, 0.9); b.box(25.0, 1.6, 26.4, 2.4)
    b.table(20.8, 15.0, 22.7, 17.0); b.table(24.3, 15.0, 26.2, 17.0); b.table(28.0, 14.5, 30.0, 17.5)
    b.dot(22.75, 7.8, 0.2)                                         # coffee machine in the alcove
    b.outside(12, dmin=1.5, dmax=5.0)
    b.person([(6.0, 7.0), (12.0, 11.0), (17.0, 16.0)], speed=0.1)
    b.person([(25.0, 10.0), (30.0, 10.0)], speed=0.08, start=400)
    b.person([(8.3, 10.8)], start=0, stop=1200)
    b.space(3.2, 2.2, "room", "lobby", region=(1.9, 0.6, 4.4, 5.4))
    b.space(14.0, 16.0, "room", "work hall", group="work hall + kitchen", region=(8.0, 15.0, 16.5, 18.0))
    b.space(8.5, 4.6, "room", "kitchen end of the work hall", group="work hall + kitchen", region=(5.6, 3.8, 11.4, 5.6))
    b.space(14.0, 3.0, "room", "quiet room", region=(12.6, 1.5, 15.4, 5.4))
    b.space(18.0, 3.8, "room", "toilets", region=(16.6, 2.2, 19.0, 5.4))
    b.space(1.75, 16.6, "room", "meeting pod A", region=(0.6, 16.1, 2.9, 17.2))
    b.space(5.25, 16.6, "room", "meeting pod B", region=(4.1, 16.1, 6.4, 17.2))
    b.space(25.0, 10.0, "hallway", "corridor + cross corridor", region=(21.0, 9.6, 30.4, 10.4))
    b.space(21.75, 13.5, "room", "meeting room 1", region=(20.6, 11.6, 22.9, 19.4))
    b.space(25.25, 13.5, "room", "meeting room 2", region=(24.1, 11.6, 26.4, 19.4))
    b.space(29.0, 13.0, "room", "meeting room 3", region=(27.6, 11.6, 30.4, 19.4))
    b.space(22.0, 6.3, "room", "office 1", region=(20.6, 5.4, 23.7, 7.0))
    b.space(26.4, 6.2, "room", "office 2", region=(24.9, 4.6, 27.9, 7.4))
    b.space(24.0, 2.0, "room", "print room", region=(20.6, 1.2, 27.9, 3.4))
    T = b.tour
    T([(2.5, 1.2), (4.2, 1.6), (2.5, 4.5), (2.5, 7.0), (6.0, 7.5), (6.0, 4.5), (11.0, 4.5), (11.0, 1.5),
       (6.0, 1.5), (6.0, 5.0), (11.0, 7.5), (13.35, 8.3), (13.35, 10.6), (10.2, 10.6), (10.2, 7.4), (14.0, 7.4),
       (14.0, 5.2), (14.0, 2.5), (14.0, 5.2), (14.0, 7.0), (18.0, 7.0), (18.0, 4.5), (18.0, 2.5), (18.0, 7.0),
       (19.0, 10.0), (21.0, 10.0), (21.0, 7.5), (21.0, 5.6), (23.0, 5.5), (21.0, 5.6), (21.0, 7.5), (21.0, 10.0),
       (22.75, 10.0), (22.75, 8.4), (22.75, 10.0), (26.5, 10.0), (26.5, 6.5), (26.5, 10.0), (29.75, 10.0),
       (29.75, 6.0), (29.75, 2.0), (27.5, 2.0), (21.0, 2.2), (27.5, 2.0), (29.75, 2.0), (29.75, 1.0),
       (29.75, 10.0), (30.5, 10.0), (29.0, 10.0), (29.0, 13.0), (29.0, 18.5), (29.0, 10.0), (25.25, 10.0),
       (25.25, 13.0), (25.25, 18.5), (25.25, 10.0), (21.75, 10.0), (21.75, 13.0), (21.75, 18.5), (21.75, 10.0),
       (19.5, 10.0), (17.0, 12.0), (14.0, 15.5), (8.0, 14.5), (5.25, 14.5), (5.25, 17.0), (5.25, 14.5),
       (1.75, 14.5), (1.75, 17.0), (1.75, 14.5), (8.0, 17.5), (12.0, 17.9), (15.5, 17.5), (17.95, 16.2),
       (14.0, 11.8), (6.0, 11.0), (2.5, 7.0), (2.5, 1.2)])
    T([(2.5, 1.2), (2.5, 7.0), (10.0, 11.0), (19.0, 10.0), (29.75, 10.0), (29.75, 3.0), (29.75, 10.0),
       (19.0, 10.0), (10.0, 16.0), (2.5, 7.0), (2.5, 1.2)], bias=(-0.05, 0.05, 0.5))
    return b


BUILDINGS = [boatyard, music_school, dental_lab, marina, farm_shop, coworking]
