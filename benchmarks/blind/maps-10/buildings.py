"""The blind11 buildings (building frame: u east, v north, metres). See README.md.
Routes are planned through listed stops with B.tour (blind8)."""
import math

from sim import B

EXT = 0.24


# ----------------------------------------------------------------------------------------------
def garden_centre():
    b = B("b11_garden_centre", "Garden centre (30 x 20 m, rotated 27 deg, 0.05 m cells; world frame at the robot's "
          "start pose inside the shop). Indoor shop behind a GLASS front with a 1.8 m sliding glass door (till "
          "counter, gondolas, display tables); a 1.8 m sliding double door into a big all-GLASS greenhouse (bench "
          "rows: two 0.8 m aisles between benches = passages; a 0.7 m slot between two benches closed by the north "
          "wall = dead end, not a passage; 1.0 m south door; a 2.4 m sliding door to the plant yard, optional) with a "
          "glass-walled tropical house in its north-east corner (1.0 m glass door); behind the shop: cafe (1.6 m "
          "opening; 1.0 m terrace door), stock room (1.0 m), office (0.8 m, through the stock room), WC (0.8 m, off "
          "the cafe). Hard: glass everywhere (rays escape into the yard), benches as solid blocks, start-pose frame.",
          (30, 20), theta=27, seed=111, margin=7.0, res=0.05, start_frame=True, pad=3.0)
    w = b.wall
    w((0, 0), (12, 0), EXT, glass=True, doors=[(6.0, 1.8, "shop sliding glass door (to outside)", None)])
    w((12, 0), (30, 0), EXT, glass=True, mullion=1.0, doors=[(9.0, 1.0, "greenhouse south door (to outside)", ("a", -1, 80))])
    w((30, 0), (30, 20), EXT, glass=True, mullion=1.0,
      doors=[(5.0, 2.4, "greenhouse sliding door to the plant yard (2.4 m wide)", None, True)])
    w((30, 20), (12, 20), EXT, glass=True, mullion=1.0)
    w((12, 20), (0, 20), EXT)
    w((0, 0), (0, 20), EXT, doors=[(16.0, 1.0, "cafe terrace door (to outside)", ("a", -1, 90))], windows=[(2.0, 5.0), (7.0, 10.0)])
    w((12, 0), (12, 20), 0.2, doors=[(6.0, 1.8, "shop to greenhouse (sliding double door)", None)])
    w((0, 12), (12, 12), 0.15, doors=[(3.0, 1.6, "shop to cafe (opening)", None),
                                      (9.5, 1.0, "shop to stock room", ("a", 1, 90))])
    w((7, 12), (7, 20), 0.12, doors=[(6.2, 0.8, "cafe to WC", ("a", -1, 90))])
    w((7, 16.5), (12, 16.5), 0.12, doors=[(3.5, 0.8, "stock room to office", ("b", 1, 90))])
    w((9, 16.5), (9, 20), 0.1)
    # tropical house: glass partitions
    w((24, 10), (30, 10), 0.03, glass=True, mullion=1.0)
    w((24, 10), (24, 20), 0.03, glass=True, mullion=1.0, doors=[(4.0, 1.0, "greenhouse to tropical house (glass door)", None)])
    # shop furniture
    b.box(8.0, 1.6, 10.2, 2.4)                                     # till counter (solid)
    b.box(2.0, 5.0, 6.0, 5.6); b.box(2.0, 7.6, 6.0, 8.2)            # gondolas
    b.table(7.5, 5.0, 9.5, 6.5); b.table(7.5, 8.0, 9.5, 9.5)        # display tables
    b.clutter((0.12, 11.9), (6.0, 11.9), -1, 2, depth=(0.3, 0.45), avoid=[(1.8, 4.2)])
    # greenhouse benches (solid: staging with crates / pots below)
    b.box(14.0, 2.0, 22.0, 3.2); b.box(14.0, 4.0, 22.0, 5.2)
    b.passage(18.0, 3.6, 0.8, "greenhouse: aisle between two bench rows", across=(0, 1))
    b.box(14.0, 6.8, 22.0, 8.0)
    b.box(14.0, 11.0, 15.2, 18.0); b.box(16.0, 11.0, 17.2, 18.0)
    b.passage(15.6, 14.5, 0.8, "greenhouse: aisle between two north-south bench rows", across=(1, 0))
    b.box(19.0, 12.5, 20.2, 19.99); b.box(20.9, 12.5, 22.1, 19.99)   # dead-end slot (closed by the north wall)
    b.box(25.0, 1.0, 28.5, 2.0)                                    # compost pallets by the south wall
    b.dot(26.0, 7.0, 0.25); b.dot(28.5, 8.2, 0.3)                  # big pots
    # tropical house
    b.box(25.5, 14.5, 27.5, 16.5)                                  # pond (hollow: inside never seen)
    b.dot(28.8, 12.0, 0.35); b.dot(25.2, 18.8, 0.3)
    # cafe
    b.box(4.5, 18.9, 6.8, 19.88)
    for u, v in [(1.5, 13.5), (4.5, 14.0), (1.8, 17.0), (4.5, 16.8)]:
        b.table(u - 0.4, v - 0.4, u + 0.4, v + 0.4); b.chair(u - 0.7, v); b.chair(u + 0.7, v)
    # stock room / office / WC
    b.clutter((7.1, 16.4), (11.9, 16.4), -1, 3, depth=(0.4, 0.5), avoid=[(3.0, 4.0)])
    b.box(11.3, 12.2, 11.88, 15.5)
    b.desk(9.2, 19.2, 11.0, 19.88, "n"); b.chair(10.0, 18.7)
    b.box(7.15, 19.3, 7.7, 19.88)
    b.outside(12, dmin=1.5, dmax=5.0)
    b.person([(6.8, 3.0), (6.8, 10.5)], speed=0.1)
    b.person([(26.5, 4.0)], start=300, stop=1400)
    b.person([(2.2, 15.0), (5.0, 15.5)], speed=0.06)
    b.space(3.5, 3.0, "room", "shop", region=(0.6, 0.6, 11.4, 11.4))
    b.space(25.0, 5.0, "room", "greenhouse", region=(12.6, 0.6, 29.4, 9.4))
    b.space(27.0, 12.5, "room", "tropical house", region=(24.6, 10.6, 29.4, 19.4))
    b.space(2.5, 15.5, "room", "cafe", region=(0.6, 12.6, 6.4, 19.4))
    b.space(9.3, 14.2, "room", "stock room", region=(7.6, 12.6, 11.0, 16.0))
    b.space(10.5, 17.8, "room", "office", region=(9.6, 17.0, 11.4, 19.0))
    b.space(8.0, 18.0, "room", "WC", region=(7.5, 17.0, 8.5, 19.3))
    T = b.tour
    T([(6.0, 1.2), (6.0, 4.0), (1.2, 4.0), (1.2, 10.5), (6.8, 9.0), (10.8, 10.5), (10.8, 3.5), (6.0, 3.5),
       (3.0, 11.0), (3.0, 13.0), (1.0, 15.8), (3.0, 18.2), (6.2, 18.2), (8.0, 17.6), (6.2, 18.2), (3.0, 13.0),
       (3.0, 11.0), (9.5, 11.0), (9.5, 13.0), (8.0, 15.5), (10.5, 15.5), (10.5, 17.8), (10.5, 15.5), (9.5, 13.0),
       (9.5, 11.0), (10.0, 6.0), (13.0, 6.0), (13.0, 1.0), (23.0, 1.2), (23.0, 3.6), (13.2, 3.6), (13.2, 6.0),
       (23.0, 6.0), (29.0, 3.5), (29.0, 8.8), (23.0, 9.0), (23.2, 14.0), (24.6, 14.0), (28.8, 11.0),
       (28.8, 19.0), (25.0, 19.2), (24.6, 14.0), (23.2, 14.0), (18.2, 19.0), (15.6, 18.8), (15.6, 10.3),
       (13.0, 10.3), (13.0, 19.0), (13.0, 10.3), (18.2, 10.0), (18.2, 12.0), (18.2, 10.0), (13.0, 6.0),
       (10.0, 6.0), (6.0, 2.0)])
    T([(6.0, 2.0), (11.0, 6.0), (20.0, 6.0), (20.0, 10.0), (13.0, 10.0), (10.0, 6.0), (3.0, 6.5), (3.0, 14.0),
       (3.0, 6.5), (6.0, 2.0)], bias=(0.06, -0.05, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def bowling():
    b = B("b11_bowling_alley", "Bowling alley (34 x 25 m, rotated -14 deg, 0.1 m cells). Entrance lobby with a shoe "
          "counter behind a 1.6 m glass double door; a bar (1.8 m opening from the lobby; 2.4 m wide arch onto the "
          "lanes, optional) with men's / women's WCs (0.8 m); the lane hall: one big room (26 x 17.5 m) of eight "
          "lanes (flat floor the lidar sees across), ball returns, settees and scoring consoles, kickback walls at "
          "the pin end in front of the pinsetters (unknown behind them); behind the pin wall a 1.8 m MACHINE "
          "CORRIDOR the width of the building (one hallway; pinsetter units along it; 0.8 m door from the hall's "
          "east side aisle); off the hall's south side: party room (1.0 m), arcade (1.6 m opening), office (0.9 m), "
          "store (0.9 m, two shelf rows with a 0.75 m aisle = passage). Hard: 0.1 m cells, lanes longer than the "
          "mapping range, big hall with furniture islands.",
          (34, 25), theta=-14, seed=112, margin=7.0, res=0.1, pad=1.0)
    w = b.wall
    w((0, 0), (34, 0), EXT, doors=[(3.0, 1.6, "lobby glass double door (to outside)", ("d", -1, 80))],
      windows=[(9.5, 14.5), (17.5, 24.5)])
    w((34, 0), (34, 25), EXT, doors=[(7.0, 1.0, "lane hall east fire exit (to outside)", ("b", -1, 90))])
    w((34, 25), (0, 25), EXT)
    w((0, 25), (0, 0), EXT)
    w((8, 0), (8, 25), 0.2, doors=[(7.5, 1.6, "lobby to lane hall (opening)", None),
                                   (14.0, 2.4, "bar to lane hall (wide arch)", None, True)])
    w((0, 10), (8, 10), 0.15, doors=[(5.0, 1.8, "lobby to bar (opening)", None)])
    w((0, 19), (8, 19), 0.15, doors=[(2.0, 0.8, "bar to men's WC", ("a", 1, 90)), (6.0, 0.8, "bar to women's WC", ("b", 1, 90))])
    w((4, 19), (4, 25), 0.12)
    w((8, 5), (34, 5), 0.2, doors=[(4.0, 1.0, "lane hall to party room", ("a", -1, 90)),
                                   (13.0, 1.6, "lane hall to arcade (opening)", None),
                                   (20.0, 0.9, "lane hall to office", ("a", -1, 90)),
                                   (24.0, 0.9, "lane hall to store", ("b", -1, 90))])
    w((16, 0), (16, 5), 0.15); w((25, 0), (25, 5), 0.15); w((29, 0), (29, 5), 0.15)
    # pin wall (back of the pinsetters) and machine corridor
    w((8, 22.5), (34, 22.5), 0.2, doors=[(25.2, 0.8, "lane hall side aisle to machine corridor", ("a", 1, 90))])
    w((32.5, 9.0), (32.5, 22.5), 0.12)                              # side-aisle wall (lanes | east aisle)
    # lanes: u 9.5..32.0, 8 lanes; ball returns and kickbacks between lane pairs
    for i in range(5):
        uk = 9.5 + i * 5.6
        b.box(uk - 0.15, 19.0, uk + 0.15, 22.4)                     # kickback wall
    for i in range(4):
        uc = 9.5 + 2.8 + i * 5.6
        b.box(uc - 0.3, 9.2, uc + 0.3, 11.0)                        # ball return
        b.box(uc - 1.0, 6.8, uc + 1.0, 7.6)                         # scoring console + settee block
        for k in (-1, 1):
            b.dot(uc + 1.4 * k, 19.6, 0.05); b.dot(uc + 1.4 * k, 20.2, 0.05)   # pins (some standing)
    # machine corridor: pinsetter units along its south side (1.8 m clear)
    for i in range(8):
        uc = 9.5 + 1.4 + i * 2.8
        b.box(uc - 0.9, 22.62, uc + 0.9, 23.0)
    b.box(9.0, 24.3, 12.0, 24.88)
    # lobby / bar
    b.box(0.12, 3.0, 1.2, 8.0)                                      # shoe counter (hollow)
    b.box(2.0, 8.5, 4.5, 9.2)                                       # shoe racks
    b.box(0.12, 11.0, 1.0, 17.0)                                    # bar counter
    for u, v in [(3.0, 12.5), (5.5, 12.5), (3.0, 15.5), (5.5, 16.5)]:
        b.table(u - 0.4, v - 0.4, u + 0.4, v + 0.4); b.chair(u - 0.7, v); b.chair(u + 0.7, v)
    b.box(0.2, 23.8, 0.9, 24.8); b.box(7.1, 23.8, 7.8, 24.8)
    # party room, arcade, office, store
    b.table(9.5, 1.5, 14.5, 2.5)
    for u in range(10, 15):
        b.chair(u, 1.0); b.chair(u, 3.0)
    for u in (17.0, 18.5, 20.0, 21.5, 23.0):
        b.box(u - 0.4, 0.2, u + 0.4, 1.1)                           # arcade machines
    b.box(18.5, 2.6, 21.0, 3.4)                                     # air hockey table (hollow)
    b.desk(25.2, 0.2, 27.2, 0.9, "s"); b.chair(26.2, 1.4)
    b.box(29.7, 1.0, 30.3, 4.2); b.box(31.05, 1.0, 31.65, 4.2)
    b.passage(30.675, 2.6, 0.75, "store: aisle between two shelf rows", across=(1, 0))
    b.box(33.3, 0.3, 33.85, 4.0)
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(12.3, 8.3), (12.3, 11.5)], speed=0.05)
    b.person([(20.0, 8.0)], start=0, stop=2000)
    b.person([(3.0, 11.5), (6.0, 17.5)], speed=0.08)
    b.space(4.5, 5.5, "room", "entrance lobby", region=(1.6, 0.6, 7.4, 9.4))
    b.space(4.0, 14.0, "room", "bar", region=(1.6, 10.6, 7.4, 18.4))
    b.space(2.0, 22.0, "room", "men's WC", region=(0.6, 19.6, 3.4, 24.4))
    b.space(6.0, 22.0, "room", "women's WC", region=(4.6, 19.6, 7.4, 24.4))
    b.space(20.0, 13.0, "room", "lane hall", region=(8.6, 5.6, 32.0, 18.6))
    b.space(21.0, 23.9, "hallway", "machine corridor", region=(8.6, 23.1, 33.4, 24.4))
    b.space(12.0, 3.8, "room", "party room", region=(8.6, 0.6, 15.4, 4.4))
    b.space(20.5, 1.8, "room", "arcade", region=(16.6, 0.6, 24.4, 4.4))
    b.space(27.0, 2.8, "room", "office", region=(25.6, 1.2, 28.4, 4.4))
    b.space(32.2, 2.5, "room", "store", region=(29.6, 0.6, 33.4, 4.4))
    T = b.tour
    T([(3.0, 1.0), (3.0, 4.5), (5.0, 8.0), (7.0, 2.0), (5.0, 8.0), (5.0, 11.5), (2.0, 13.0), (4.5, 18.0),
       (2.0, 18.5), (2.0, 21.5), (2.0, 18.5), (6.0, 18.5), (6.0, 21.5), (6.0, 18.5), (6.5, 14.0), (9.0, 14.0),
       (9.0, 8.3), (15.0, 8.3), (15.0, 11.5), (15.0, 8.3), (26.0, 8.3), (26.0, 11.5), (26.0, 8.3), (33.2, 8.3),
       (33.2, 21.5), (33.2, 23.8), (9.0, 23.8), (33.2, 23.8), (33.2, 21.5), (33.2, 6.0), (32.0, 5.9),
       (32.0, 4.5), (30.7, 4.5), (30.7, 0.7), (30.7, 4.5), (32.0, 5.9), (28.0, 5.9), (28.0, 4.2), (27.0, 2.0),
       (28.0, 4.2), (28.0, 5.9), (21.0, 5.9), (21.0, 4.0), (23.8, 2.0), (17.5, 2.0), (21.0, 4.0), (21.0, 5.9),
       (12.0, 5.9), (12.0, 4.0), (9.0, 3.8), (15.0, 3.8), (12.0, 4.0), (12.0, 5.9), (9.0, 6.0), (5.0, 7.5), (3.0, 1.0)])
    T([(3.0, 1.0), (5.0, 7.5), (9.0, 8.3), (30.0, 8.3), (30.0, 12.0), (20.0, 12.0), (9.0, 8.3), (5.0, 7.5),
       (3.0, 1.0)], bias=(-0.07, 0.05, -0.5))
    return b



# ----------------------------------------------------------------------------------------------
def archive():
    b = B("b11_archive", "Records archive (28 x 16 m, rotated 71 deg, 0.05 m cells, a short-range 8 m lidar). A 2 m "
          "corridor the length of the building (one hallway, with a 2 x 1.5 m alcove holding a copier and a 2.5 m "
          "wide junction with a cross corridor running south to a 1.2 m exit double door: the T is one hallway; 1.0 m "
          "fire exit at the west end); north: stack room (1.2 m double door) with a bank of MOBILE SHELVING (carriages "
          "packed together against the north wall, one 0.8 m aisle open = dead-end slot, not a passage) and two "
          "static shelf rows + a wall shelf (0.8 and 0.9 m aisles open at both ends = passages), a reading room "
          "behind a GLASS wall (0.9 m glass door), strong room (1.0 m), conservation lab (0.9 m); south: search room "
          "(1.0 m street door, 1.2 m to the corridor, 0.8 m to processing), processing room (0.9 m to the corridor, 0.9 "
          "m to the cross corridor), kitchen (0.8 m) and a WC with a 0.7 m door off the cross corridor, receiving room "
          "(1.6 m double door). Hard: 8 m lidar range on a 28 m corridor, dead-end shelving slot, alcove.",
          (28, 16), theta=71, seed=113, margin=7.0, res=0.05, pad=1.0, rmax=8.0, rmap=7.5)
    w = b.wall
    w((0, 0), (28, 0), EXT, doors=[(14.25, 1.2, "cross corridor south exit double door (to outside)", ("d", -1, 85))])
    w((28, 0), (28, 16), EXT)
    w((28, 16), (0, 16), EXT)
    w((0, 0), (0, 16), EXT, doors=[(3.5, 1.0, "search room street door (to outside)", ("a", -1, 90)),
                                   (8.0, 1.0, "corridor west fire exit (to outside)", ("b", 1, 90))])
    # corridor walls
    w((0, 7), (13, 7), 0.15, doors=[(3.0, 1.2, "corridor to search room (double door)", ("d", -1, 90)),
                                    (10.0, 0.9, "corridor to processing room", ("a", -1, 90))])
    w((15.5, 7), (28, 7), 0.15, doors=[(8.5, 1.6, "corridor to receiving room (double door)", ("d", -1, 90))])
    w((0, 9), (12, 9), 0.15, doors=[(6.0, 1.2, "corridor to stack room (double door)", ("d", 1, 90))])
    w((12, 9), (19, 9), 0.03, glass=True, mullion=1.0, doors=[(3.5, 0.9, "corridor to reading room (glass door)", ("a", 1, 85))])
    w((19, 10.5), (21, 10.5), 0.15)                                  # alcove back wall
    w((21, 9), (28, 9), 0.15, doors=[(1.75, 1.0, "corridor to strong room", ("a", 1, 90)),
                                     (5.25, 0.9, "corridor to conservation lab", ("b", 1, 90))])
    w((12, 9), (12, 16), 0.15); w((19, 9), (19, 16), 0.15); w((21, 9), (21, 16), 0.2); w((24.5, 9), (24.5, 16), 0.15)
    # south side
    w((6, 0), (6, 7), 0.15, doors=[(2.0, 0.8, "search room to processing room", ("a", 1, 90))])
    w((13, 0), (13, 7), 0.15, doors=[(3.5, 0.9, "processing room to cross corridor", ("b", -1, 90))])
    w((15.5, 0), (15.5, 7), 0.15, doors=[(2.0, 0.8, "cross corridor to kitchen", ("a", -1, 90)),
                                         (5.5, 0.7, "cross corridor to WC", ("a", -1, 90))])
    w((15.5, 4), (20, 4), 0.12)
    w((20, 0), (20, 7), 0.15)
    w((18, 4), (18, 7), 0.12, doors=[(1.5, 0.8, "cleaner's cupboard (closed)", None, False, True)])
    # stack room: mobile shelving bank (dead-end aisle) + static rows
    u = 0.2
    for i in range(5):
        b.box(u, 10.4, u + 1.0, 15.99)
        u += 1.0 + (0.8 if i == 2 else 0.0)
    b.box(8.2, 10.6, 8.8, 14.6); b.box(9.6, 10.6, 10.2, 14.6); b.box(11.1, 10.6, 11.88, 14.6)
    b.passage(9.2, 12.6, 0.8, "stack room: aisle between two static shelf rows", across=(1, 0))
    b.passage(10.65, 12.6, 0.9, "stack room: aisle between a shelf row and the wall shelf", across=(1, 0))
    b.box(6.6, 15.0, 7.8, 15.88)                                     # map cabinet
    # reading room
    for uu, vv in [(14.0, 11.0), (17.0, 11.0), (14.0, 14.0), (17.0, 14.0)]:
        b.table(uu - 0.8, vv - 0.5, uu + 0.8, vv + 0.5)
        b.chair(uu - 0.4, vv - 0.85); b.chair(uu + 0.4, vv + 0.85)
    b.box(12.1, 15.3, 14.0, 15.88)
    b.box(19.3, 9.9, 20.2, 10.42)                                    # copier in the alcove
    # strong room: shelving along the walls; lab benches
    b.box(21.1, 10.0, 21.7, 15.88); b.box(23.8, 10.0, 24.4, 15.88); b.box(21.7, 15.3, 23.8, 15.88)
    b.box(24.6, 14.9, 27.88, 15.88); b.box(27.2, 9.5, 27.88, 13.0); b.table(25.3, 11.2, 26.6, 12.6)
    # south rooms
    b.box(0.12, 0.12, 0.7, 2.6); b.desk(2.0, 0.5, 4.5, 1.3, "s"); b.chair(3.2, 1.8)
    b.table(7.5, 2.5, 11.0, 4.2); b.box(6.1, 0.12, 12.9, 0.6)
    b.box(15.6, 3.3, 19.9, 3.9); b.box(19.2, 0.12, 19.9, 1.5)
    b.box(15.6, 6.3, 16.1, 6.9)
    for uu in (21.5, 23.5, 25.5):
        b.box(uu - 0.6, 0.8, uu + 0.6, 2.0)                          # pallets of boxes
    b.box(26.8, 4.0, 27.88, 6.5)
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(2.0, 8.0), (26.0, 8.0)], speed=0.12, start=0, stop=700)
    b.person([(13.0, 12.5), (17.5, 12.5)], speed=0.04)
    b.space(8.0, 8.0, "hallway", "corridor (with the cross corridor and the alcove)", region=(0.6, 7.6, 27.4, 8.4))
    b.space(3.0, 4.5, "room", "search room", region=(0.8, 2.0, 5.4, 6.4))
    b.space(9.5, 5.5, "room", "processing room", region=(6.6, 1.0, 12.4, 6.4))
    b.space(17.5, 2.0, "room", "staff kitchen", region=(16.1, 0.6, 19.4, 3.0))
    b.space(16.75, 5.5, "room", "WC", region=(16.1, 4.6, 17.4, 6.4))
    b.space(24.0, 4.5, "room", "receiving room", region=(20.6, 2.5, 27.4, 6.4))
    b.space(7.0, 12.5, "room", "stack room", region=(6.0, 9.6, 11.4, 15.4))
    b.space(15.5, 12.5, "room", "reading room", region=(12.6, 9.6, 18.4, 15.4))
    b.space(22.75, 12.0, "room", "strong room", region=(21.8, 9.6, 23.7, 15.0))
    b.space(26.0, 10.5, "room", "conservation lab", region=(25.1, 9.6, 27.0, 14.6))
    T = b.tour
    T([(1.0, 3.5), (3.0, 3.5), (3.0, 6.0), (1.2, 6.3), (4.8, 2.5), (5.2, 2.0), (7.0, 2.0), (11.8, 1.5),
       (12.0, 5.5), (7.0, 5.5), (10.0, 6.4), (10.0, 8.0), (6.0, 8.0), (6.0, 9.8), (3.6, 9.8),
       (7.0, 10.0), (7.0, 14.4), (10.65, 15.2), (10.65, 10.0), (9.2, 10.0), (9.2, 15.2),
       (7.0, 14.4), (6.0, 9.8), (6.0, 8.0), (1.0, 8.0), (14.25, 8.0), (14.25, 1.0), (14.25, 3.5), (12.5, 3.5),
       (14.25, 3.5), (14.25, 2.0), (17.5, 2.0), (14.25, 2.0), (14.25, 5.5), (16.75, 5.5), (14.25, 5.5),
       (14.25, 8.0), (15.5, 8.0), (15.5, 9.8), (12.8, 12.5), (18.3, 15.2), (18.3, 9.8), (15.5, 9.8), (15.5, 8.0),
       (20.0, 8.0), (22.75, 8.0), (22.75, 12.0), (22.75, 8.0), (24.0, 8.0), (24.0, 6.0), (21.0, 3.0), (27.2, 3.0),
       (24.0, 6.0), (24.0, 8.0), (26.25, 8.0), (26.0, 11.0), (26.0, 8.0), (27.3, 8.0), (14.25, 8.0),
       (14.25, 6.0)])
    T([(14.25, 6.0), (14.25, 8.0), (2.0, 8.0), (26.5, 8.0), (14.25, 8.0), (14.25, 6.0)], bias=(0.05, 0.06, -0.45))
    return b


# ----------------------------------------------------------------------------------------------
def bar_front(b, u0, u1, v, gate_at, gw, note):
    """A pen front of vertical bars along v from u0 to u1, with an open gate (gw wide, centre gate_at):
    the gate is an OPTIONAL door (an opening in a bar front: a person may or may not call it a door)."""
    a, c = gate_at - gw / 2, gate_at + gw / 2
    b.bars((u0, v), (a - 0.03, v), gap=0.05, r=0.02); b.bars((c + 0.03, v), (u1, v), gap=0.05, r=0.02)
    b.box(a - 0.06, v - 0.04, a, v + 0.04); b.box(c, v - 0.04, c + 0.06, v + 0.04)
    b.seg((c + 0.06, v - 0.03), (c + 0.06, v - 0.03 - gw * 0.9), 0.03)   # the open gate (bars, swung into the pen)
    b.doors.append({"center": (gate_at, v), "width_m": gw, "optional": True, "note": note, "t": (1.0, 0.0),
                    "n": (0.0, 1.0), "glass": True, "th": 0.1})


def animal_shelter():
    b = B("b11_animal_shelter", "Animal shelter kennel block (31 x 14 m, rotated 203 deg, 0.05 m cells, front-facing "
          "270 deg lidar, PARTLY EXPLORED). Reception behind a GLASS front (1.0 m glass street door; counter), exam "
          "room (0.9 m), a 1.2 m double door into a 2 m kennel corridor (one hallway; 1.2 m door to the exercise yard "
          "at its east end); north side: cat room (0.9 m; cat cages along the walls), seven dog pens with solid block "
          "fronts and 0.7 m gates, food store (0.8 m); south side: grooming room (0.9 m; a 0.7 m squeeze between the "
          "bath and the grooming table = passage), seven pens with BAR fronts (gates optional: openings in a bar "
          "front), laundry (0.8 m). The robot turned back two thirds of the way down the corridor: the east pens, "
          "food store, laundry and the yard door are seen only from afar or not at all (dropped / ignore boxes). "
          "Pens are seen only through their gates or bars.",
          (31, 14), theta=203, seed=114, margin=7.0, res=0.05, fov=270.0, pad=1.0)
    w = b.wall
    w((0, 0), (31, 0), EXT, windows=[(1.5, 4.5), (7.5, 10.5)])
    w((31, 0), (31, 14), EXT, doors=[(7.0, 1.2, "corridor door to the exercise yard (to outside)", ("a", -1, 90))])
    w((31, 14), (0, 14), EXT)
    w((0, 0), (0, 6), EXT)
    w((0, 6), (0, 14), EXT, glass=True, mullion=1.0, doors=[(4.0, 1.0, "reception glass street door (to outside)", None)])
    w((0, 6), (6, 6), 0.15, doors=[(3.0, 0.9, "reception to exam room", ("a", -1, 90))])
    w((6, 0), (6, 14), 0.2, doors=[(7.0, 1.2, "reception to kennel corridor (double door)", ("d", -1, 90))])
    w((6, 8), (31, 8), 0.2, doors=[(3.0, 0.9, "corridor to cat room", ("a", 1, 90))] +
      [(6.0 + 1.2 + 2.4 * i, 0.7, f"corridor to dog pen N{i + 1} (gate)", ("a", 1, 90)) for i in range(7)] +
      [(23.9, 0.8, "corridor to food store", ("b", 1, 90))])
    w((6, 6), (12, 6), 0.2, doors=[(3.0, 0.9, "corridor to grooming room", ("a", -1, 90))])
    w((28.8, 6), (31, 6), 0.2, doors=[(1.1, 0.8, "corridor to laundry", ("b", -1, 90))])
    for i in range(8):
        uu = 12 + 2.4 * i
        w((uu, 8), (uu, 14), 0.15)
        w((uu, 0), (uu, 6), 0.15)
    for i in range(7):
        uu = 12 + 2.4 * i
        bar_front(b, uu + 0.08, uu + 2.32, 6.0, uu + 1.2, 0.8, f"corridor to dog pen S{i + 1} (gate in a bar front, optional)")
    # reception
    b.box(3.0, 11.5, 5.5, 12.3); b.box(5.0, 12.3, 5.88, 13.88)      # counter (hollow) + filing
    b.box(0.3, 6.6, 2.2, 7.1)                                       # bench under the glass
    # exam room
    b.box(2.0, 2.0, 3.6, 2.8); b.box(0.12, 4.8, 2.5, 5.88); b.box(4.8, 0.12, 5.88, 2.0)
    # grooming room: bath + grooming table with a 0.7 m squeeze
    b.box(6.12, 1.6, 7.3, 3.2); b.box(8.0, 2.0, 9.6, 2.8)
    b.passage(7.65, 2.4, 0.7, "grooming room: squeeze between the bath and the grooming table", across=(1, 0))
    b.box(10.5, 0.12, 11.9, 0.8)
    # cat room: cages along the walls (hollow boxes)
    b.box(6.12, 12.9, 11.92, 13.92); b.box(11.2, 9.5, 11.92, 12.9); b.dot(8.0, 10.8, 0.25)
    # dog pens: a bed in each (box at the back)
    for i in range(7):
        uu = 12 + 2.4 * i
        b.box(uu + 0.3, 12.6, uu + 1.3, 13.5)
        b.box(uu + 1.0, 0.5, uu + 2.0, 1.4)
    b.box(29.0, 12.0, 30.88, 13.88); b.box(29.5, 0.12, 30.88, 1.5)
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(8.0, 7.0), (19.0, 7.0)], speed=0.07, start=0, stop=900)
    b.person([(16.2, 12.0)], start=0, stop=4000)              # volunteer standing in pen N2
    b.space(3.0, 9.5, "room", "reception", region=(0.8, 7.6, 5.4, 11.0))
    b.space(3.0, 4.0, "room", "exam room", region=(0.6, 0.6, 5.4, 4.5))
    b.space(15.0, 7.0, "hallway", "kennel corridor", region=(6.6, 6.6, 30.4, 7.4))
    b.space(9.0, 10.8, "room", "cat room", region=(6.6, 8.6, 11.0, 12.4))
    b.space(9.0, 4.5, "room", "grooming room", region=(6.6, 3.4, 11.4, 5.4))
    for i in range(7):
        uu = 12 + 2.4 * i
        b.space(uu + 1.2, 10.5, "room", f"dog pen N{i + 1}", region=(uu + 0.6, 8.6, uu + 1.8, 12.2))
        b.space(uu + 1.2, 3.5, "room", f"dog pen S{i + 1}", region=(uu + 0.6, 1.8, uu + 1.8, 5.4))
    b.space(29.9, 10.5, "room", "food store", region=(29.4, 8.6, 30.4, 11.6))
    b.space(29.9, 3.5, "room", "laundry", region=(29.4, 1.8, 30.4, 5.4))
    T = b.tour
    T([(1.2, 10.0), (3.0, 10.0), (1.2, 13.0), (4.5, 9.0), (3.0, 7.0), (3.0, 5.0), (1.2, 3.5), (4.5, 3.5),
       (3.0, 5.0), (3.0, 7.0), (4.5, 7.0), (7.5, 7.0), (9.0, 7.0), (9.0, 9.0), (7.0, 11.5), (10.0, 11.0),
       (9.0, 9.0), (9.0, 7.0), (9.0, 5.0), (7.65, 4.2), (7.65, 0.8), (10.0, 1.2), (10.0, 4.0), (9.0, 5.0),
       (9.0, 7.0), (20.0, 7.0), (21.0, 7.0)], clear=0.3)
    T([(21.0, 7.0), (15.0, 7.0), (7.5, 7.0), (4.5, 7.0), (2.0, 9.0)], bias=(0.05, -0.06, 0.55))
    return b


# ----------------------------------------------------------------------------------------------
def pharmacy():
    b = B("b11_pharmacy", "Community pharmacy (20 x 13 m, rotated -37 deg, 0.025 m cells). Shop floor behind a GLASS "
          "front with a 1.6 m sliding glass door (no leaves): gondola rows (a 0.9 m gap between two gondola units and "
          "a 0.8 m gap between a gondola end and a promotion stand = passages; a 0.7 m slot between two wall units "
          "closed by the wall = dead end, not a passage), the dispensing counter with a 0.7 m lift-flap gap (passage; "
          "the only way behind the counter); a 1.0 m door behind the counter into the dispensary (two dispensing "
          "shelf rows with a 0.8 m aisle = passage), a 0.8 m door from the dispensary to the staff room, WC (0.7 m, "
          "through the staff room); consultation room (0.8 m) and stock room (1.0 m; 1.0 m rear fire exit) off the "
          "shop. Hard: very fine cells, glass front, counter and shelving gaps vs doors, small rooms.",
          (20, 13), theta=-37, seed=115, margin=6.0, res=0.025, pad=0.5)
    w = b.wall
    w((0, 0), (20, 0), EXT, glass=True, mullion=1.5, doors=[(4.0, 1.6, "shop sliding glass door (to outside)", None)])
    w((20, 0), (20, 13), EXT, windows=[(1.0, 5.0)])
    w((20, 13), (0, 13), EXT, doors=[(15.0, 1.0, "stock room rear fire exit (to outside)", ("a", 1, 90))])
    w((0, 13), (0, 0), EXT)
    w((0, 8), (20, 8), 0.15, doors=[(1.75, 0.8, "shop to consultation room", ("a", 1, 90)),
                                    (6.0, 1.0, "shop to stock room", ("b", 1, 90)),
                                    (17.5, 1.0, "behind the counter to the dispensary", ("a", 1, 90))])
    w((3.5, 8), (3.5, 13), 0.12); w((9, 8), (9, 13), 0.15)
    w((12, 8), (12, 13), 0.15, doors=[(3.75, 0.8, "dispensary to staff room", ("b", 1, 90))])
    w((9, 10.5), (12, 10.5), 0.12, doors=[(1.5, 0.7, "staff room to WC", ("a", -1, 90))])
    # shop: gondolas
    b.box(6.0, 2.4, 10.2, 3.0); b.box(11.1, 2.4, 14.0, 3.0)
    b.passage(10.65, 2.7, 0.9, "shop: gap between two gondola units", across=(1, 0))
    b.box(6.0, 4.2, 14.0, 4.8); b.box(14.8, 4.2, 15.6, 4.8)
    b.passage(14.4, 4.5, 0.8, "shop: gap between a gondola end and a promotion stand", across=(1, 0))
    b.box(0.12, 5.0, 2.0, 5.6); b.box(0.12, 6.3, 2.0, 6.9)           # two wall units: a dead-end slot between
    b.box(0.12, 1.0, 0.6, 4.2)                                        # wall shelving
    b.box(18.5, 0.6, 19.88, 1.6)                                      # chiller
    # dispensing counter (solid) with a return to the wall; lift-flap gap
    b.box(11.0, 6.0, 16.0, 6.7); b.box(16.7, 6.0, 19.88, 6.7); b.box(11.0, 6.7, 11.6, 7.93)
    b.passage(16.35, 6.35, 0.7, "lift-flap gap in the dispensing counter", across=(1, 0))
    # dispensary
    b.box(14.5, 9.4, 14.9, 11.8); b.box(15.7, 9.4, 16.1, 11.8)
    b.passage(15.3, 10.6, 0.8, "dispensary: aisle between two dispensing shelf rows", across=(1, 0))
    b.box(19.2, 8.5, 19.88, 12.88); b.box(12.3, 12.3, 14.0, 12.88)
    # consultation, stock, staff room, WC
    b.table(0.8, 10.0, 2.0, 11.0); b.chair(0.6, 11.6); b.chair(2.6, 10.5); b.box(0.12, 12.4, 1.2, 12.88)
    b.box(3.62, 9.0, 4.1, 12.88); b.box(8.4, 8.5, 8.92, 12.88); b.box(5.5, 10.2, 7.0, 10.8)
    b.table(9.2, 11.9, 10.2, 12.8)
    b.box(11.3, 8.1, 11.92, 8.7)
    b.outside(10, dmin=1.0, dmax=4.0)
    b.person([(8.0, 3.6), (13.0, 3.6)], speed=0.06)
    b.person([(19.3, 7.3)], start=0, stop=1500)
    b.space(4.0, 2.0, "room", "shop floor", region=(0.8, 0.6, 11.0, 7.4))
    b.space(1.75, 9.3, "room", "consultation room", region=(0.6, 8.6, 2.9, 12.0))
    b.space(6.0, 9.5, "room", "stock room", region=(4.6, 8.6, 7.9, 12.4))
    b.space(10.5, 9.25, "room", "WC", region=(9.6, 8.6, 11.4, 9.9))
    b.space(10.6, 11.3, "room", "staff room", region=(9.6, 10.8, 11.4, 12.4))
    b.space(17.5, 10.5, "room", "dispensary", region=(16.6, 8.6, 18.6, 12.4))
    T = b.tour
    T([(4.0, 1.0), (4.0, 3.6), (1.2, 3.6), (1.2, 7.3), (4.5, 7.3), (3.5, 5.95), (4.5, 7.3), (1.75, 7.3),
       (1.75, 9.3), (2.6, 11.8), (1.75, 9.3), (1.75, 7.3), (6.0, 7.3), (6.0, 9.3), (5.0, 12.0), (7.5, 12.0),
       (6.0, 9.3), (6.0, 7.3), (10.5, 7.3), (10.65, 2.0), (10.65, 3.6), (14.4, 3.6), (14.4, 5.4), (16.35, 5.4),
       (16.35, 7.3), (12.2, 7.2), (17.5, 7.3), (17.5, 9.0), (15.3, 9.0), (15.3, 12.2), (17.5, 12.2), (17.5, 9.0),
       (13.0, 9.0), (13.0, 11.75), (11.2, 11.75), (10.5, 11.0), (10.5, 9.25), (10.5, 11.0), (11.2, 11.75),
       (13.0, 11.75), (17.5, 9.0), (17.5, 7.3), (16.35, 7.3), (16.35, 5.4), (19.0, 3.0), (16.0, 1.2),
       (7.0, 1.2), (4.0, 1.0)], clear=0.3)
    T([(4.0, 1.0), (7.0, 3.6), (13.0, 3.6), (16.35, 5.4), (7.0, 5.4), (4.0, 1.0)], bias=(-0.05, 0.05, 0.45))
    return b


# ----------------------------------------------------------------------------------------------
def youth_club():
    b = B("b11_youth_club", "Youth club (26 x 18 m, rotated 118 deg, 0.05 m cells; world frame at the robot's start "
          "pose in the entrance lobby, a big unknown canvas around the map). A 14 x 18 m main hall (one room) with a "
          "raised stage at its north end (a solid block on the map: the stage top is never seen), a table-tennis "
          "table, a sofa line against the west wall with a 0.75 m gap (passage), a 2.4 m double fire door (optional: "
          "wider than a door) and a chair store (1.0 m); entrance lobby (1.8 m double street door; 1.6 m double door "
          "into the hall; 1.6 m opening onto the corridor); a 2 m corridor with a 2.5 m corridor branching north at a "
          "wide junction (one hallway; 1.0 m fire exits at both ends; 1.0 m door into the hall); games room (1.2 m; "
          "pool table with unknown inside), music room (0.9 m), kitchen (0.9 m), office (0.8 m), two toilets "
          "(0.8 m; cubicles).",
          (26, 18), theta=118, seed=116, margin=7.0, res=0.05, start_frame=True, pad=5.0)
    w = b.wall
    w((0, 0), (26, 0), EXT, doors=[(7.0, 2.4, "hall double fire door (2.4 m, to outside)", ("d", -1, 85), True),
                                   (17.0, 1.8, "lobby double street door (to outside)", ("d", 1, 90))],
      windows=[(1.5, 4.5), (10.0, 12.5)])
    w((26, 0), (26, 18), EXT, doors=[(7.0, 1.0, "corridor east fire exit (to outside)", ("a", 1, 90))])
    w((26, 18), (0, 18), EXT, doors=[(4.75, 1.0, "north corridor exit (to outside)", ("b", -1, 90))])
    w((0, 18), (0, 0), EXT, windows=[(4.0, 8.0), (10.0, 14.0)])
    w((14, 0), (14, 18), 0.2, doors=[(3.0, 1.6, "lobby to hall (double door)", ("d", 1, 90)),
                                     (7.0, 1.0, "corridor to hall", ("a", 1, 90))])
    w((14, 6), (20, 6), 0.15, doors=[(3.0, 1.6, "lobby to corridor (opening)", None)])
    w((20, 0), (20, 6), 0.15)
    w((20, 6), (26, 6), 0.15, doors=[(1.5, 0.8, "corridor to boys' toilets", ("a", -1, 90)),
                                     (4.5, 0.8, "corridor to girls' toilets", ("b", -1, 90))])
    w((23, 0), (23, 6), 0.12)
    w((14, 8), (20, 8), 0.15, doors=[(3.0, 1.2, "corridor to games room", ("a", 1, 90))])
    w((22.5, 8), (26, 8), 0.15)
    w((20, 8), (20, 18), 0.15, doors=[(8.0, 0.9, "north corridor to music room", ("a", 1, 90))])
    w((14, 13), (20, 13), 0.15)
    w((22.5, 8), (22.5, 18), 0.15, doors=[(2.0, 0.9, "north corridor to kitchen", ("a", -1, 90)),
                                          (7.0, 0.8, "north corridor to office", ("b", -1, 90))])
    w((22.5, 12.5), (26, 12.5), 0.12)
    w((0, 15), (2, 15), 0.12, doors=[(1.0, 1.0, "hall to chair store", ("a", 1, 90))])
    w((2, 15), (2, 18), 0.12)
    # toilets: cubicle partitions
    for u0 in (20.0, 23.0):
        for k in range(3):
            b.seg((u0 + 0.9 * k + 0.9, 0.12), (u0 + 0.9 * k + 0.9, 1.5), 0.04)
        b.seg((u0 + 0.1, 1.5), (u0 + 0.5, 1.5), 0.04)
    # hall
    b.box(2.06, 15.5, 13.9, 17.88)                                    # stage (solid riser; top unseen)
    b.box(0.12, 2.0, 2.3, 2.9); b.box(3.05, 2.0, 5.3, 2.9)            # sofa line (west wall) with a 0.75 m gap
    b.passage(2.675, 2.45, 0.75, "hall: gap between two sofas", across=(1, 0))
    b.table(1.2, 3.6, 2.4, 4.3)                                       # coffee table (legs)
    b.table(6.0, 8.0, 8.7, 9.5)                                       # table-tennis table
    b.box(12.8, 10.0, 13.88, 14.0)                                    # stacked tables
    b.table(9.0, 2.5, 11.0, 3.5); b.chair(8.6, 3.0); b.chair(11.4, 3.0)
    # lobby, games, music, kitchen, office
    b.box(18.6, 1.5, 19.88, 3.8)                                      # reception desk (hollow)
    b.box(15.5, 10.0, 18.2, 11.5)                                     # pool table (hollow)
    b.box(14.2, 12.0, 15.2, 12.8)                                     # table football
    b.box(14.12, 16.6, 16.0, 17.88); b.box(18.9, 16.2, 19.9, 17.9)    # amps, piano
    for a in range(0, 360, 60):
        b.dot(16.5 + 0.55 * math.cos(math.radians(a)), 14.6 + 0.55 * math.sin(math.radians(a)), 0.1)
    b.box(25.3, 8.1, 25.88, 12.4); b.box(22.6, 11.8, 25.0, 12.4)
    b.desk(23.5, 17.2, 25.5, 17.88, "n"); b.chair(24.5, 16.6)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(4.0, 6.0), (11.0, 11.0)], speed=0.1)
    b.person([(7.35, 10.2)], start=0, stop=2500)
    b.person([(16.0, 13.6), (18.5, 13.6)], speed=0.05)
    b.space(7.0, 6.0, "room", "main hall", region=(0.8, 0.8, 13.2, 14.8))
    b.space(16.0, 4.0, "room", "entrance lobby", region=(14.6, 0.6, 18.0, 5.4))
    b.space(21.25, 12.0, "hallway", "corridor (with the north branch)", region=(20.6, 6.6, 22.0, 17.4))
    b.space(16.0, 9.5, "room", "games room", region=(14.6, 8.6, 19.4, 12.4))
    b.space(18.0, 14.8, "room", "music room", region=(14.6, 13.6, 19.4, 17.4))
    b.space(24.2, 10.0, "room", "kitchen", region=(23.1, 8.6, 25.0, 11.4))
    b.space(24.2, 15.0, "room", "office", region=(23.1, 13.1, 25.4, 16.6))
    b.space(21.5, 3.5, "room", "boys' toilets", region=(20.6, 1.9, 22.4, 5.4))
    b.space(24.5, 3.5, "room", "girls' toilets", region=(23.6, 1.9, 25.4, 5.4))
    b.space(1.0, 16.5, "room", "chair store", region=(0.6, 15.6, 1.5, 17.4))
    T = b.tour
    T([(17.0, 1.2), (16.0, 3.0), (15.0, 3.0), (12.0, 3.0), (12.0, 1.0), (6.0, 1.0), (2.675, 1.2), (2.675, 3.4),
       (1.0, 5.5), (5.0, 5.5), (5.0, 11.0), (1.0, 14.0), (1.0, 16.5), (1.0, 14.0), (9.5, 14.5), (12.0, 9.0),
       (12.0, 7.0), (15.0, 7.0), (17.0, 7.0), (17.0, 9.0), (14.8, 9.0), (19.0, 9.0), (19.0, 12.2), (17.0, 9.0),
       (17.0, 7.0), (21.25, 7.0), (21.5, 4.5), (21.25, 7.0), (24.5, 7.0), (24.5, 4.5), (24.5, 7.0), (25.5, 7.0),
       (21.25, 7.0), (21.25, 10.0), (23.5, 10.0), (24.2, 9.0), (23.5, 10.0), (21.25, 10.0), (21.25, 15.0),
       (23.5, 15.0), (24.5, 14.0), (23.5, 15.0), (21.25, 15.0), (21.25, 16.0), (19.5, 16.0), (17.0, 15.0),
       (17.5, 13.7), (19.5, 16.0), (21.25, 16.0), (21.25, 17.3), (21.25, 7.0), (17.0, 7.0), (17.0, 1.2)])
    T([(17.0, 1.2), (17.0, 7.0), (21.25, 7.0), (21.25, 16.5), (21.25, 7.0), (15.0, 7.0), (12.0, 7.0),
       (7.0, 5.0), (15.0, 3.0), (17.0, 1.2)], bias=(0.07, 0.04, -0.5))
    return b


BUILDINGS = [garden_centre, bowling, archive, animal_shelter, pharmacy, youth_club]
