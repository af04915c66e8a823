"""The blind9 buildings (building frame: u east, v north, metres). See README.md.
Routes are planned through listed stops with B.tour (blind8)."""
import math

from sim import B

EXT = 0.24


def car(b, cu, cv, ang, L=4.5, W=1.8):
    """A car body as the lidar sees it at ~0.3 m: a solid box (bumpers / doors / wheels)."""
    b.rbox(cu, cv, L, W, ang)


# ----------------------------------------------------------------------------------------------
def airport():
    b = B("b9_airport_terminal", "Small regional airport terminal (40 x 20 m, axis-aligned, 0.05 m cells; world frame at "
          "the robot's start pose, so the origin is not the building's corner; a big unknown border around the "
          "map). Check-in hall behind a GLASS front with two 1.8 m sliding glass doors (check-in counter islands, "
          "seat rows, queue posts); a security checkpoint (1.6 m open entry from the hall; two x-ray lines and two "
          "walk-through detector arches of 0.75 m = passages; 1.2 m exit into the lounge); a 10 x 20 m departure "
          "lounge (bench rows, cafe, two 1.2 m gate doors to the apron); a 2 m landside corridor (one hallway) with the "
          "airline office, baggage make-up hall (1.6 m double door, carousel island, baggage carts), staff room and "
          "two toilets. Passengers walking. Hard: glass front, big open halls, detector arches that are passages, not "
          "doors.", (40, 20), theta=0, seed=51, margin=7.0, res=0.05, pad=6.0, start_frame=True)
    w = b.wall
    w((0, 0), (24, 0), glass=True, doors=[(6.0, 1.8, "check-in hall south glass sliding door (to outside)", None),
                                          (16.0, 1.8, "check-in hall east glass sliding door (to outside)", None)])
    w((24, 0), (40, 0), EXT, windows=[(8.0, 14.0)])
    w((40, 0), (40, 20), EXT, doors=[(4.0, 1.2, "lounge to apron, gate 1", ("a", -1, 85)),
                                     (14.0, 1.2, "lounge to apron, gate 2", ("b", -1, 90))],
      windows=[(6.5, 11.5)])
    w((40, 20), (0, 20), EXT, windows=[(2.0, 5.0), (34.0, 38.0)])
    w((0, 20), (0, 0), EXT)
    # corridor v 10..12, u 0..30
    w((0, 10), (30, 10), 0.15, doors=[(1.5, 1.0, "check-in hall to landside corridor (staff door)", ("a", -1, 90))])
    w((0, 12), (30, 12), 0.15, doors=[(3.0, 0.9, "corridor to airline office", ("a", 1, 90)),
                                      (12.0, 1.6, "corridor to baggage make-up hall (double door)", ("d", 1, 88)),
                                      (21.0, 0.9, "corridor to staff room", ("b", 1, 90)),
                                      (25.5, 0.9, "corridor to men's toilet", ("a", 1, 90)),
                                      (28.5, 0.9, "corridor to women's toilet", ("b", 1, 90))])
    w((24, 0), (24, 10), 0.15, doors=[(8.8, 1.6, "check-in hall to security checkpoint (open entry)", None)])
    w((30, 0), (30, 20), 0.2, doors=[(4.0, 1.2, "security checkpoint to departure lounge", None),
                                     (11.0, 1.0, "landside corridor to departure lounge (staff door)", ("a", -1, 90))])
    w((6, 12), (6, 20)); w((18, 12), (18, 20)); w((24, 12), (24, 20)); w((27, 12), (27, 20))
    # check-in hall: counter islands, seat rows, queue posts, kiosk
    for u0 in (2.0, 9.0, 16.0):
        b.box(u0, 7.0, u0 + 5.0, 7.7)
        b.box(u0 + 0.5, 9.3, u0 + 4.5, 9.92)                  # feed belt against the corridor wall
        for k in range(6):
            b.dot(u0 + 0.4 + k * 0.85, 5.2, 0.04)             # queue posts
    for u0 in (1.5, 9.0, 19.0):
        b.box(u0, 1.6, u0 + 3.0, 2.1)                          # seat rows
    b.rbox(21.5, 4.3, 1.2, 1.2, 20)                            # kiosk
    b.clutter((0.12, 0.5), (0.12, 9.5), -1, 2, avoid=[(1.0, 2.0)])
    # security: x-ray lines A, B, divider C, detector arches at u 27.8
    b.box(25.4, 2.4, 28.6, 3.2); b.box(25.4, 4.8, 28.6, 5.6); b.box(25.4, 7.2, 28.6, 7.6)
    for v0, v1 in ((3.2, 3.6), (4.35, 4.8), (5.6, 6.0), (6.75, 7.2)):
        b.box(27.72, v0, 27.88, v1)
    b.passage(27.8, 3.975, 0.75, "security: walk-through detector arch, lane 1", across=(0, 1))
    b.passage(27.8, 6.375, 0.75, "security: walk-through detector arch, lane 2", across=(0, 1))
    b.box(24.2, 0.2, 25.6, 1.0)                                # supervisor desk
    # lounge: bench rows, cafe, duty free gondolas
    for v0 in (6.5, 8.5, 10.5):
        b.box(32.5, v0, 37.0, v0 + 0.55)
    b.box(31.0, 17.4, 35.0, 18.1); b.box(34.3, 18.1, 35.0, 19.88)      # cafe counter
    for (u0, v0) in ((31.5, 14.5), (33.5, 14.5)):
        b.table(u0, v0, u0 + 0.8, v0 + 0.8)
        b.chair(u0 + 0.4, v0 - 0.35); b.chair(u0 + 0.4, v0 + 1.15)
    b.box(36.6, 16.0, 37.6, 18.5)                                        # duty-free gondola (double-sided)
    b.clutter((30.1, 0.12), (40, 0.12), 1, 3, depth=(0.3, 0.5))
    # airline office, bag hall, staff room, toilets
    b.desk(0.5, 17.0, 2.5, 17.8, "n"); b.desk(3.5, 17.0, 5.5, 17.8, "n"); b.chair(1.5, 16.5); b.chair(4.5, 16.5)
    b.box(0.12, 12.5, 0.6, 15.0)
    b.box(9.0, 14.6, 15.0, 17.4)                               # carousel island
    for u0 in (7.0, 15.8):
        b.box(u0, 18.6, u0 + 1.6, 19.4)                        # baggage carts
    b.box(16.8, 12.6, 17.88, 13.6)
    b.table(19.0, 15.5, 21.0, 16.5); b.chair(19.5, 15.1); b.chair(20.5, 17.0); b.box(22.8, 12.6, 23.88, 19.88)
    for u0 in (24, 27):
        for uu in (u0 + 1.0, u0 + 2.0):
            b.seg((uu, 19.88), (uu, 18.4), 0.05)               # cubicle partitions
        b.box(u0 + 0.12, 12.6, u0 + 0.6, 14.4)                 # basins
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(4.0, 3.5), (20.0, 3.5)], speed=0.2)
    b.person([(32.0, 3.0), (38.0, 3.0), (38.0, 13.0)], speed=0.12, start=400)
    b.person([(11.5, 6.3)], start=0, stop=700)
    b.space(12.0, 4.0, "room", "check-in hall", region=(0.6, 0.6, 23.4, 9.4))
    b.space(26.3, 8.8, "room", "security checkpoint", region=(24.6, 7.9, 29.4, 9.5))
    b.space(35.0, 3.5, "room", "departure lounge", region=(30.6, 0.6, 39.4, 19.4))
    b.space(15.0, 11.0, "hallway", "landside corridor", region=(0.6, 10.5, 29.4, 11.5))
    b.space(3.0, 14.5, "room", "airline office", region=(0.8, 12.6, 5.4, 19.4))
    b.space(12.0, 13.5, "room", "baggage make-up hall", region=(6.6, 12.6, 17.4, 19.4))
    b.space(21.0, 14.0, "room", "staff room", region=(18.6, 12.6, 22.6, 19.4))
    b.space(25.5, 16.0, "room", "men's toilet", region=(24.6, 14.6, 26.4, 18.2))
    b.space(28.5, 16.0, "room", "women's toilet", region=(27.6, 14.6, 29.4, 18.2))
    T = b.tour
    T([(6.0, 1.0), (6.0, 4.0), (1.2, 4.0), (1.2, 8.0), (8.0, 8.2), (8.5, 6.0), (15.0, 6.0), (15.5, 8.2), (22.5, 8.2),
       (22.5, 6.0), (15.0, 3.0), (22.0, 1.0), (22.5, 8.8), (26.3, 8.8), (29.3, 8.8), (29.3, 6.4), (24.6, 6.375),
       (24.5, 3.975), (29.3, 3.975), (29.3, 1.6), (26.0, 1.6), (29.3, 4.0), (31.0, 4.0), (35.0, 3.5), (38.8, 4.0),
       (38.8, 12.0), (35.0, 12.2), (31.2, 12.0), (31.2, 16.5), (36.0, 15.5), (38.5, 15.5), (38.5, 19.2), (36.0, 15.5),
       (31.0, 11.0), (29.0, 11.0), (21.0, 11.0), (21.0, 14.0), (21.6, 18.8), (21.0, 14.0), (21.0, 11.0), (12.0, 11.0),
       (12.0, 13.5), (7.0, 13.5), (7.2, 17.8), (16.0, 18.0), (16.0, 13.5), (12.0, 13.5), (12.0, 11.0), (3.0, 11.0),
       (3.0, 14.5), (3.0, 11.0), (1.5, 11.0), (1.5, 9.3), (6.0, 4.0), (6.0, 1.0)])
    T([(6.0, 1.0), (6.0, 4.0), (1.5, 9.3), (1.5, 11.0), (25.5, 11.0), (25.5, 13.8), (25.5, 11.0), (28.5, 11.0),
       (28.5, 13.8), (28.5, 11.0), (29.0, 11.0), (31.0, 11.0), (35.0, 13.0), (35.0, 5.0), (31.0, 4.0), (29.3, 4.0),
       (29.3, 8.8), (23.0, 8.8), (12.0, 4.0), (6.0, 1.2)], bias=(0.06, -0.07, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def print_shop():
    b = B("b9_print_shop", "Print and copy shop (18 x 12 m, rotated 33 deg, 0.025 m cells). Shop behind a GLASS "
          "shopfront with a 1.0 m glass door (service counter with a 0.8 m lift-flap gap = passage, a self-service "
          "copier, display racks); production room (1.0 m from the shop's staff side; two big digital presses with "
          "a 0.8 m gap between them = passage, a guillotine, a binding bench, plotters; 1.0 m fire exit); paper store "
          "(0.9 m; shelving rows with 0.8 and 0.9 m aisles = passages); despatch room (1.2 m; 1.0 m side door to "
          "outside); office, kitchenette and a WC behind it. Staff walking. Hard: fine cells, small rooms, machine "
          "gaps that are passages, glass front.", (18, 12), theta=33, seed=52, margin=6.0, res=0.025)
    w = b.wall
    w((0, 0), (8, 0), glass=True, doors=[(4.0, 1.0, "shop glass entrance door (to outside)", None)], mullion=1.0)
    w((8, 0), (18, 0), EXT, windows=[(2.0, 4.0), (6.0, 8.0)])
    w((18, 0), (18, 12), EXT, doors=[(2.0, 1.0, "production room fire exit (to outside)", ("b", -1, 85)),
                                     (10.0, 1.0, "despatch side door (to outside)", ("a", -1, 80))])
    w((18, 12), (0, 12), EXT)
    w((0, 12), (0, 0), EXT, windows=[(7.5, 10.0)])
    w((8, 0), (8, 12), 0.15, doors=[(5.2, 1.0, "shop (staff side) to production room", ("b", -1, 90))])
    w((0, 6), (8, 6), 0.12, doors=[(2.5, 0.9, "shop to office", ("a", 1, 90)),
                                   (6.5, 0.8, "shop to kitchenette", ("b", 1, 90))])
    w((5, 6), (5, 12))
    w((5, 9.5), (8, 9.5), doors=[(1.5, 0.8, "kitchenette to WC", ("b", 1, 90))])
    w((8, 8), (18, 8), 0.15, doors=[(4.3, 0.9, "production room to paper store", ("b", 1, 90)),
                                    (7.5, 1.2, "production room to despatch room", ("a", 1, 88))])
    w((13, 8), (13, 12))
    # shop: counter with a lift-flap gap, display cabinet, copier, racks
    b.box(0.12, 3.8, 6.0, 4.4)
    b.box(6.8, 3.8, 7.925, 4.4)
    b.passage(6.4, 4.1, 0.8, "shop: lift-flap gap in the service counter", across=(1, 0))
    b.box(0.12, 0.5, 0.6, 2.6)                                  # display rack
    b.box(5.8, 1.6, 7.1, 2.4)                                   # self-service copier
    b.box(0.12, 5.2, 1.4, 5.88)                                 # shelf behind the counter
    # production: presses with a 0.8 m gap, guillotine, bench, plotters, pallet
    b.box(9.5, 2.0, 12.5, 3.2); b.box(9.5, 4.0, 12.5, 5.2)
    b.passage(11.0, 3.6, 0.8, "production: gap between the two digital presses", across=(0, 1))
    b.box(14.5, 2.5, 15.8, 3.6)                                 # guillotine
    b.table(14.0, 5.6, 16.8, 6.5)                               # binding bench
    b.box(8.075, 6.6, 9.5, 7.925)                               # pallet of paper
    b.box(16.6, 0.5, 17.88, 1.4)                                # plotter
    b.box(13.0, 0.12, 14.4, 0.7)
    # office
    b.desk(0.5, 10.2, 2.3, 11.0, "n"); b.chair(1.4, 9.7); b.box(3.6, 11.0, 4.94, 11.88); b.box(0.12, 6.6, 0.5, 8.6)
    # kitchenette, WC
    b.box(7.3, 6.1, 7.94, 8.6); b.table(5.4, 7.6, 6.2, 8.4)
    b.box(7.3, 11.2, 7.88, 11.88); b.box(5.1, 10.8, 5.6, 11.4)
    # paper store: shelving rows N-S
    b.box(8.075, 8.9, 8.7, 11.88)
    b.box(9.5, 9.2, 10.1, 10.8); b.box(11.0, 9.2, 11.6, 10.8)
    b.passage(9.1, 10.0, 0.8, "paper store: aisle between the wall shelf and shelf row 1", across=(1, 0))
    b.passage(10.55, 10.0, 0.9, "paper store: aisle between shelf rows 1 and 2", across=(1, 0))
    # despatch: stacked boxes, packing table
    b.box(16.5, 8.075, 17.88, 9.2); b.box(13.1, 10.8, 14.6, 11.88); b.table(15.0, 10.6, 16.6, 11.4)
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(9.0, 6.8), (16.5, 6.8)], speed=0.12)
    b.person([(3.0, 2.5)], start=0, stop=500)
    b.space(3.0, 2.2, "room", "shop", region=(0.6, 0.5, 7.4, 3.5))
    b.space(13.5, 4.5, "room", "production room", region=(8.5, 0.6, 17.5, 7.5))
    b.space(12.2, 9.9, "room", "paper store", region=(11.7, 8.5, 12.6, 11.6))
    b.space(15.5, 9.9, "room", "despatch room", region=(13.5, 8.5, 17.4, 11.5))
    b.space(2.5, 8.6, "room", "office", region=(0.7, 6.5, 4.5, 11.5))
    b.space(6.5, 7.3, "room", "kitchenette", region=(5.5, 6.5, 7.2, 9.0))
    b.space(6.5, 10.85, "room", "WC", region=(5.6, 10.0, 7.4, 11.5))
    T = b.tour
    T([(4.0, -0.6), (4.0, 1.0), (1.2, 3.0), (5.2, 3.0), (6.4, 3.2), (6.4, 5.0), (2.5, 5.0), (2.5, 7.2), (1.5, 8.6),
       (4.2, 9.5), (2.5, 7.2), (2.5, 5.0), (6.5, 5.0), (6.5, 7.0), (6.5, 9.0), (6.5, 10.85), (6.5, 9.0), (6.5, 7.0),
       (6.5, 5.0), (7.5, 5.2), (9.0, 5.4), (13.5, 5.0), (13.0, 3.6), (9.0, 3.6), (9.0, 1.3), (16.0, 1.5), (17.3, 2.2),
       (17.2, 4.5), (13.5, 7.2), (12.3, 7.2), (12.3, 9.5), (12.2, 11.3), (10.55, 11.3), (10.55, 8.6), (9.1, 8.6),
       (9.1, 11.3), (10.55, 11.3), (12.2, 9.5), (12.3, 7.2), (15.5, 7.2), (15.5, 9.9), (17.2, 10.0), (14.0, 9.6),
       (15.5, 7.2), (9.0, 5.4), (7.5, 5.2), (4.0, 3.0), (4.0, 1.0)])
    T([(4.0, 1.0), (4.0, 3.0), (7.5, 5.2), (11.0, 6.0), (11.0, 1.3), (16.0, 1.3), (15.5, 9.9), (12.3, 7.2),
       (7.5, 5.2), (4.0, 1.0)], bias=(-0.05, 0.06, -0.45))
    return b



# ----------------------------------------------------------------------------------------------
def bakery():
    b = B("b9_bakery", "Bakery production floor with a shop (30 x 16 m, rotated -21 deg, 0.1 m cells). Shop (1.0 m "
          "street door; a glass display counter leaving a 0.88 m gap at the west wall = passage; bread racks), a "
          "22 x 11 m production hall (1.0 m door from the shop's staff side, 1.2 m from the packing room; deck ovens, "
          "rack oven, spiral mixers, a row of solid steel work benches and a moulding line with 0.8 m and 0.9 m gaps "
          "between them = passages, cooling-rack trolleys, 1.8 m loading double door); along the north side, each "
          "off the hall: proving room (1.2 m), cold room (1.0 m), flour store (1.2 m; sacks on pallets), changing room "
          "(0.9 m), office (0.9 m); packing room (0.9 m from the shop) and staff canteen behind it. No corridor. "
          "Bakers walking. Hard: coarse cells, many rooms opening straight off one big hall, bench gaps that are "
          "passages.", (30, 16), theta=-21, seed=53, margin=7.0, res=0.1)
    w = b.wall
    w((0, 0), (30, 0), EXT, doors=[(4.0, 1.0, "shop street door (to outside)", ("a", 1, 90))],
      windows=[(1.0, 3.0), (5.2, 7.5), (22.5, 25.5)])
    w((30, 0), (30, 16), EXT, doors=[(4.0, 1.8, "production hall loading double door (to outside)", ("d", -1, 80))])
    w((30, 16), (0, 16), EXT)
    w((0, 16), (0, 0), EXT, windows=[(13.5, 15.5)])
    w((8, 0), (8, 11), 0.15, doors=[(4.9, 1.0, "shop (staff side) to production hall", ("b", -1, 90)),
                                    (8.5, 1.2, "packing room to production hall", ("a", -1, 90))])
    w((8, 11), (8, 16), 0.15)
    w((0, 6), (8, 6), 0.12, doors=[(6.0, 0.9, "shop to packing room", ("a", 1, 90))])
    w((0, 11), (30, 11), 0.15, doors=[(4.0, 0.9, "packing room to staff canteen", ("b", 1, 90)),
                                      (10.0, 1.2, "production hall to proving room", ("a", 1, 90)),
                                      (14.0, 1.0, "production hall to cold room", ("b", 1, 85)),
                                      (19.0, 1.2, "production hall to flour store", ("a", 1, 90)),
                                      (24.0, 0.9, "production hall to changing room", ("b", 1, 90)),
                                      (28.0, 0.9, "production hall to office", ("a", 1, 90))])
    w((12, 11), (12, 16), 0.2); w((16, 11), (16, 16), 0.2); w((22, 11), (22, 16)); w((26, 11), (26, 16))
    # shop
    b.box(1.0, 3.4, 7.925, 4.0)                                 # glass display counter (solid front)
    b.passage(0.56, 3.7, 0.88, "shop: gap between the display counter and the west wall", across=(1, 0))
    b.box(1.0, 5.4, 5.0, 5.94)                                  # bread racks
    b.table(5.2, 1.0, 6.8, 2.0)
    # production hall
    b.box(12.5, 0.12, 15.0, 2.2); b.box(16.0, 0.12, 18.5, 2.2)   # deck ovens
    b.box(20.0, 0.12, 21.6, 1.8)                                 # rack oven
    b.box(9.0, 0.5, 10.0, 1.5); b.box(9.0, 1.9, 10.0, 2.9)       # spiral mixers
    b.box(11.0, 5.0, 15.0, 6.2); b.box(15.8, 5.0, 19.8, 6.2)     # steel work benches
    b.box(20.7, 5.0, 28.0, 5.8)                                  # moulding line
    b.passage(15.4, 5.6, 0.8, "production hall: gap between the two work benches", across=(1, 0))
    b.passage(20.25, 5.4, 0.9, "production hall: gap between the bench row and the moulding line", across=(1, 0))
    for u0 in (12.2, 16.5, 21.0):
        b.box(u0, 9.9, u0 + 0.6, 10.7)                           # cooling-rack trolleys
    b.box(27.5, 0.3, 29.0, 1.5)                                  # pallet
    b.clutter((29.88, 6.0), (29.88, 10.8), 1, 2, depth=(0.3, 0.5))
    # north rooms
    b.box(8.075, 12.0, 9.0, 15.9)                                # proofers
    b.box(12.1, 11.5, 12.7, 15.9); b.box(15.3, 11.5, 15.9, 15.9)  # cold-room shelving
    b.box(16.5, 13.5, 18.0, 15.9); b.box(19.0, 13.5, 20.5, 15.9); b.box(21.0, 11.5, 21.9, 13.0)   # flour pallets
    b.box(22.1, 15.4, 25.9, 15.925); b.box(23.0, 13.0, 25.0, 13.4)                               # lockers, bench
    b.desk(26.5, 14.8, 28.5, 15.6, "n"); b.chair(27.5, 14.3); b.box(29.3, 12.0, 29.88, 13.6)
    # packing room, canteen
    b.box(1.0, 8.0, 5.0, 9.0); b.box(0.12, 6.5, 0.7, 10.5)
    b.box(4.5, 15.3, 7.88, 15.88)
    for v0 in (12.5, 14.3):
        b.table(1.0, v0, 2.6, v0 + 0.8)
        b.chair(1.4, v0 - 0.35); b.chair(2.2, v0 - 0.35)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(10.5, 4.0), (26.0, 3.5)], speed=0.12)
    b.person([(16.8, 7.5)], start=0, stop=600)
    b.space(3.0, 2.3, "room", "shop", region=(0.6, 0.6, 7.4, 3.0))
    b.space(24.0, 8.0, "room", "production hall", region=(8.6, 0.6, 29.4, 10.4))
    b.space(6.3, 7.5, "room", "packing room", region=(5.2, 6.5, 7.5, 10.5))
    b.space(5.5, 13.5, "room", "staff canteen", region=(3.0, 11.5, 7.5, 15.2))
    b.space(10.5, 13.5, "room", "proving room", region=(9.3, 11.6, 11.5, 15.5))
    b.space(14.0, 13.5, "room", "cold room", region=(12.9, 12.2, 15.1, 15.5))
    b.space(19.0, 12.3, "room", "flour store", region=(16.5, 11.5, 20.8, 13.2))
    b.space(23.5, 14.2, "room", "changing room", region=(22.5, 11.6, 25.5, 15.0))
    b.space(28.5, 13.0, "room", "office", region=(26.5, 11.6, 29.2, 14.3))
    T = b.tour
    T([(4.0, 1.5), (1.5, 2.5), (0.56, 3.0), (0.56, 4.6), (3.0, 4.7), (6.0, 4.7), (6.0, 7.2), (6.3, 7.5), (6.8, 9.8),
       (4.0, 10.0), (4.0, 12.0), (5.5, 13.5), (3.6, 14.0), (6.5, 12.0), (4.0, 12.0), (4.0, 10.0), (7.2, 9.8),
       (7.3, 8.5), (9.5, 8.5), (10.5, 4.0), (15.4, 3.5), (15.4, 7.5), (20.25, 7.5), (20.25, 3.5), (26.0, 3.5),
       (29.0, 3.0), (29.0, 9.0), (24.0, 9.0), (24.0, 12.0), (23.5, 14.2), (24.0, 12.0), (24.0, 9.0), (28.0, 9.0),
       (28.0, 12.5), (28.5, 13.0), (28.0, 9.0), (19.0, 9.0), (19.0, 12.3), (19.0, 9.0), (14.0, 9.0), (14.0, 13.5),
       (14.0, 9.0), (10.0, 9.0), (10.0, 12.5), (10.5, 13.5), (10.0, 9.0), (9.5, 8.5), (7.0, 8.5), (6.0, 7.2),
       (6.0, 4.7), (0.56, 4.6), (0.56, 3.0), (4.0, 1.5)])
    T([(4.0, 1.5), (1.5, 2.5), (0.56, 3.0), (0.56, 4.6), (7.0, 4.9), (9.5, 4.9), (20.25, 3.5), (29.0, 6.5),
       (11.0, 8.8), (9.5, 4.9), (7.0, 4.9), (0.56, 4.6), (0.56, 3.0), (4.0, 1.5)], bias=(0.07, 0.05, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def pod(b, cu, cv):
    """A four-desk pod (2 x 2 desks of 1.6 x 0.8 m, screen panels on the inner edges) with chairs."""
    b.desk(cu - 1.6, cv - 0.8, cu, cv, "n"); b.desk(cu, cv - 0.8, cu + 1.6, cv, "n")
    b.desk(cu - 1.6, cv, cu, cv + 0.8, "s"); b.desk(cu, cv, cu + 1.6, cv + 0.8, "s")
    for du in (-0.8, 0.8):
        b.chair(cu + du, cv - 1.2); b.chair(cu + du, cv + 1.2)


def town_hall():
    b = B("b9_town_hall", "Town hall council floor (44 x 20 m, rotated 67 deg, 0.05 m cells). A 2.4 m corridor the "
          "length of the floor (one hallway; 1.0 m fire exits at both ends); south: a 22 x 9 m open-plan office with "
          "six four-desk pods (two 1.6 m double doors) and a GLASS meeting room in its east corner (0.9 m glass "
          "door), the council chamber (1.8 m double door; a solid horseshoe of council desks, a public gallery behind "
          "a rail with a 0.8 m gate gap = passage), committee rooms 1 and 2; north: an ante room (0.9 m) with the "
          "mayor's office behind it (0.9 m, reached only through the ante room), the entrance lobby (1.6 m entrance "
          "double door, 1.8 m opening onto the corridor), a meeting room, kitchen, WC, records room, committee room "
          "3. PARTLY EXPLORED: the robot never went east of the chamber door, so the east end (committee rooms, "
          "records room) is seen only from the corridor, from afar. Hard: long open-plan floor with desk pods, a "
          "room reached through a room, a half-mapped wing.", (44, 20), theta=67, seed=54, margin=7.0, res=0.05)
    w = b.wall
    w((0, 0), (44, 0), EXT, windows=[(1.5, 5.0), (6.5, 10.0), (11.5, 15.0), (16.5, 20.5), (24.0, 32.0), (36.0, 38.0),
                                     (40.5, 42.5)])
    w((44, 0), (44, 20), EXT, doors=[(10.2, 1.0, "corridor east fire exit (to outside)", ("a", -1, 85))])
    w((44, 20), (0, 20), EXT, doors=[(30.0, 1.6, "lobby entrance double door (to outside)", ("d", -1, 85))],
      windows=[(2.0, 4.0), (16.0, 20.0), (36.0, 42.0)])
    w((0, 20), (0, 0), EXT, doors=[(9.8, 1.0, "corridor west fire exit (to outside)", ("b", -1, 85))])
    w((0, 9), (44, 9), 0.15, doors=[(5.0, 1.6, "corridor to open-plan office, west double door", ("d", -1, 88)),
                                    (16.0, 1.6, "corridor to open-plan office, east double door", ("d", -1, 90)),
                                    (28.0, 1.8, "corridor to council chamber (double door)", ("d", -1, 85)),
                                    (36.5, 0.9, "corridor to committee room 1", ("a", -1, 90)),
                                    (41.5, 0.9, "corridor to committee room 2", ("b", -1, 90))])
    w((0, 11.4), (44, 11.4), 0.15, doors=[(2.5, 0.9, "corridor to ante room", ("a", 1, 90)),
                                          (14.0, 1.8, "corridor to entrance lobby (open)", None),
                                          (20.0, 0.9, "corridor to meeting room", ("b", 1, 90)),
                                          (25.0, 0.9, "corridor to kitchen", ("a", 1, 90)),
                                          (28.5, 0.9, "corridor to WC", ("b", 1, 90)),
                                          (33.0, 1.0, "corridor to records room", ("a", 1, 90)),
                                          (40.0, 0.9, "corridor to committee room 3", ("b", 1, 90))])
    w((22, 0), (22, 9), 0.2); w((34, 0), (34, 9)); w((39, 0), (39, 9))
    w((5, 11.4), (5, 20), doors=[(5.1, 0.9, "ante room to mayor's office", ("a", -1, 90))])
    for u in (11, 17, 23, 27, 30, 36):
        w((u, 11.4), (u, 20))
    # glass meeting room in the open plan (u 18..22, v 4.5..9)
    w((18, 4.5), (22, 4.5), glass=True)
    w((18, 9), (18, 4.5), glass=True, doors=[(2.5, 0.9, "open-plan office to glass meeting room (glass door)", ("a", 1, 90))])
    b.table(19.0, 6.2, 21.0, 7.4)
    for du in (0.5, 1.5):
        b.chair(19.0 + du, 5.8); b.chair(19.0 + du, 7.8)
    # open plan: pods, printer, cabinets
    for cu in (3.5, 8.5, 13.5):
        for cv in (2.5, 6.2):
            pod(b, cu, cv)
    b.box(16.6, 0.4, 17.6, 1.1); b.box(0.12, 4.0, 0.6, 5.5)
    # chamber: horseshoe of solid desks (open to the south), rail with a gate gap
    b.arc(28.0, 4.2, 2.5, 0, 180, th=0.6)
    b.seg((25.5, 4.2), (25.5, 3.4), 0.6); b.seg((30.5, 4.2), (30.5, 3.4), 0.6)
    for a in range(20, 180, 30):
        b.chair(28.0 + 1.7 * math.cos(math.radians(a)), 4.2 + 1.7 * math.sin(math.radians(a)))
    b.seg((22.1, 1.8), (27.6, 1.8), 0.06); b.seg((28.4, 1.8), (33.925, 1.8), 0.06)
    b.passage(28.0, 1.8, 0.8, "council chamber: gate gap in the public gallery rail", across=(1, 0))
    for u in (23.5, 25.0, 31.0, 32.5):
        b.chair(u, 0.9, 0)
    # committee rooms
    for u0 in (34.0, 39.0):
        b.table(u0 + 1.0, 3.0, u0 + 4.0, 5.0)
    b.table(37.5, 14.0, 42.5, 16.0)
    # records room: shelves along the walls
    b.box(30.1, 12.0, 30.7, 19.88); b.box(35.3, 12.0, 35.925, 19.88); b.box(31.5, 19.3, 34.5, 19.88)
    # ante room, mayor's office, lobby, meeting, kitchen, WC
    b.desk(0.5, 17.5, 2.5, 18.3, "n"); b.chair(1.5, 17.0); b.box(0.12, 12.0, 0.6, 14.0)
    b.desk(7.0, 17.0, 9.5, 18.0, "n"); b.chair(8.2, 16.5); b.box(9.6, 12.0, 10.925, 13.0); b.box(5.1, 18.8, 8.0, 19.88)
    b.box(11.5, 16.5, 13.2, 17.2); b.box(15.5, 12.0, 16.925, 12.6)                               # reception, bench
    b.table(18.5, 14.5, 21.5, 16.5)
    for du in (0.6, 1.5, 2.4):
        b.chair(18.5 + du, 14.1); b.chair(18.5 + du, 16.9)
    b.box(23.1, 19.3, 26.925, 19.88); b.box(26.4, 14.0, 26.925, 19.3)
    b.seg((28.0, 19.88), (28.0, 18.3), 0.05); b.seg((29.0, 19.88), (29.0, 18.3), 0.05)
    b.box(0.2, 9.6, 0.7, 9.925)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(2.0, 10.2), (26.0, 10.2)], speed=0.2)
    b.person([(6.0, 4.3), (15.0, 4.3)], speed=0.1, start=300)
    b.person([(14.0, 14.5)], start=0, stop=800)
    b.space(8.5, 4.35, "room", "open-plan office", region=(0.8, 0.6, 17.4, 8.4))
    b.space(20.0, 8.1, "room", "glass meeting room", region=(18.6, 5.0, 21.4, 8.5))
    b.space(24.0, 5.0, "room", "council chamber", region=(22.6, 2.3, 33.4, 8.4))
    b.space(36.5, 4.5, "room", "committee room 1", region=(34.6, 0.6, 38.4, 8.4))
    b.space(41.5, 4.5, "room", "committee room 2", region=(39.6, 0.6, 43.4, 8.4))
    b.space(16.0, 10.2, "hallway", "corridor", region=(0.6, 9.6, 43.4, 10.8))
    b.space(2.5, 14.5, "room", "ante room", region=(0.8, 12.0, 4.4, 16.8))
    b.space(8.0, 14.5, "room", "mayor's office", region=(5.6, 12.0, 10.4, 16.3))
    b.space(14.0, 14.5, "room", "entrance lobby", region=(11.6, 12.0, 16.4, 19.4))
    b.space(20.0, 13.0, "room", "meeting room", region=(17.6, 12.0, 22.4, 19.4))
    b.space(25.0, 16.0, "room", "kitchen", region=(23.6, 12.0, 25.9, 18.9))
    b.space(28.5, 15.5, "room", "WC", region=(27.6, 12.0, 29.4, 18.0))
    b.space(33.0, 15.5, "room", "records room", region=(31.3, 12.0, 34.7, 18.9))
    b.space(40.0, 17.5, "room", "committee room 3", region=(36.6, 12.0, 43.4, 19.4))
    T = b.tour
    T([(14.0, 18.5), (12.5, 14.0), (14.0, 12.0), (14.0, 10.2), (5.0, 10.2), (5.0, 8.0), (1.2, 7.8), (1.2, 4.35),
       (6.0, 4.35), (6.0, 0.9), (11.0, 0.9), (11.0, 4.35), (16.0, 4.35), (16.8, 6.5), (17.0, 6.7),
       (18.8, 6.7), (20.0, 8.1), (18.8, 6.7), (17.0, 6.7), (16.0, 8.0), (16.0, 10.2), (28.0, 10.2), (28.0, 8.0),
       (24.0, 7.5), (24.0, 3.0), (28.0, 2.6), (28.0, 0.9), (26.5, 0.9), (28.0, 0.9), (28.0, 2.6),
       (32.0, 3.0), (32.0, 7.5), (28.0, 8.0), (28.0, 10.2), (31.0, 10.2), (28.5, 10.2), (28.5, 12.8), (28.5, 10.2),
       (25.0, 10.2), (25.0, 13.5), (25.0, 10.2), (20.0, 10.2), (20.0, 13.0), (22.2, 13.0), (22.2, 18.5), (17.8, 18.5),
       (17.8, 13.0), (20.0, 13.0), (20.0, 10.2), (2.5, 10.2), (2.5, 12.5), (4.2, 15.5), (6.0, 15.5), (8.0, 14.5),
       (10.2, 15.5), (6.0, 15.5), (2.5, 12.5), (2.5, 10.2), (0.8, 10.2), (8.0, 10.2), (14.0, 12.0), (14.0, 18.5)])
    T([(14.0, 18.5), (14.0, 10.2), (16.0, 10.2), (16.0, 4.35), (1.5, 4.35), (5.0, 8.0), (5.0, 10.2), (30.0, 10.2),
       (14.0, 11.0), (14.0, 18.5)], bias=(-0.06, 0.08, -0.55))
    return b


# ----------------------------------------------------------------------------------------------
def car_dealership():
    b = B("b9_car_dealership", "Car dealership with a workshop, plus a detached wash bay (site 39 x 18 m, rotated "
          "-8 deg, 0.05 m cells; world frame at the robot's start pose; map cropped tight to the mapped area). "
          "Showroom behind a GLASS corner (two glass walls, a 1.8 m glass sliding double door; three cars, sales "
          "desks) with a customer lounge (1.6 m opening), two glass-fronted sales offices (0.9 m glass doors) and a "
          "customer WC (0.8 m); a 1.2 m door into the workshop (two two-post car lifts, a car, tool chests; a "
          "tyre-storage alcove grouped with the workshop floor), a parts store (1.0 m; three shelf rows with two "
          "0.9 m aisles = passages) and the workshop office (0.9 m). A SECOND ISLAND: the wash bay across the yard "
          "(its own 1.2 m door, a 0.9 m door to a valet store) was mapped after the robot was carried over; the yard "
          "between was never seen. Hard: glass corner, cars as big obstacles, alcove, two disconnected islands.",
          (39, 18), theta=-8, seed=55, margin=7.0, res=0.05, pad=0.0, start_frame=True)
    b.set_footprint([(0, 0), (30, 0), (30, 18), (0, 18)], [(33, 2), (39, 2), (39, 12), (33, 12)])
    w = b.wall
    w((0, 0), (16, 0), glass=True, doors=[(8.0, 1.8, "showroom glass sliding double door (to outside)", None)])
    w((16, 0), (30, 0), EXT, windows=[(1.5, 3.5)])
    w((30, 0), (30, 18), EXT, doors=[(9.0, 1.0, "workshop side door (closed)", None, False, True)])
    w((30, 18), (0, 18), EXT, windows=[(2.0, 4.0), (25.0, 28.5)])
    w((0, 18), (0, 12), EXT)
    w((0, 12), (0, 0), glass=True)
    w((0, 12), (6, 12), doors=[(3.0, 1.6, "showroom to customer lounge (opening)", None)])
    w((6, 12), (14, 12), glass=True, doors=[(2.0, 0.9, "showroom to sales office 1 (glass door)", ("a", 1, 90)),
                                            (6.0, 0.9, "showroom to sales office 2 (glass door)", ("b", 1, 90))])
    w((14, 12), (16, 12), doors=[(1.0, 0.8, "showroom to customer WC", ("b", 1, 90))])
    w((6, 12), (6, 18)); w((10, 12), (10, 18)); w((14, 12), (14, 18))
    w((16, 0), (16, 18), 0.2, doors=[(6.0, 1.2, "showroom to workshop", ("a", -1, 90))])
    w((16, 12), (22, 12), doors=[(3.0, 1.0, "workshop to parts store", ("a", 1, 90))])
    w((22, 12), (22, 18)); w((26, 12), (26, 18))
    w((26, 12), (30, 12), doors=[(2.0, 0.9, "workshop to workshop office", ("b", 1, 90))])
    # wash bay island
    w((33, 2), (39, 2), EXT); w((39, 12), (33, 12), EXT); w((33, 12), (33, 2), EXT)
    w((39, 2), (39, 12), EXT, doors=[(3.0, 1.2, "wash bay door (to the yard)", ("a", -1, 85))])
    w((33, 8), (39, 8), doors=[(4.0, 0.9, "wash bay to valet store", ("b", 1, 90))])
    # showroom
    car(b, 4.2, 4.0, 30); car(b, 11.0, 3.8, -20); car(b, 6.5, 9.0, 0)
    b.table(11.8, 8.3, 13.4, 9.1); b.chair(12.6, 7.9); b.chair(12.2, 9.5); b.chair(13.0, 9.5)
    b.dot(14.8, 1.2, 0.1)
    # lounge, offices, WC
    b.box(0.12, 15.5, 0.9, 17.88); b.box(2.0, 17.2, 5.0, 17.88); b.table(2.5, 14.2, 3.5, 15.0)
    for u0 in (6, 10):
        b.desk(u0 + 0.6, 16.2, u0 + 3.0, 17.0, "n"); b.chair(u0 + 1.8, 15.7); b.chair(u0 + 1.2, 14.2); b.chair(u0 + 2.4, 14.2)
    b.box(14.1, 17.2, 14.6, 17.88); b.box(15.4, 15.8, 15.925, 16.4)
    # workshop
    for u in (18.0, 21.0, 23.6, 26.6):
        b.box(u, 2.0, u + 0.4, 2.6)                              # lift posts
    car(b, 20.0, 8.0, 90)
    b.clutter((29.88, 0.3), (29.88, 11.7), 1, 4, depth=(0.4, 0.6), length=(0.6, 1.0))
    b.box(22.1, 12.5, 22.7, 17.88); b.box(25.3, 12.5, 25.9, 17.88)   # tyre racks in the alcove
    b.box(23.0, 17.3, 25.0, 17.88)                                   # workbench
    # parts store: three shelf rows E-W with 0.9 m aisles
    for v0 in (13.4, 14.8, 16.2):
        b.box(17.3, v0, 20.0, v0 + 0.5)                     # 1.2 m cross aisle along the west wall
    b.passage(18.65, 14.35, 0.9, "parts store: aisle between shelf rows 1 and 2", across=(0, 1))
    b.passage(18.65, 15.75, 0.9, "parts store: aisle between shelf rows 2 and 3", across=(0, 1))
    b.desk(27.0, 16.8, 29.0, 17.6, "n"); b.chair(28.0, 16.3); b.box(29.3, 13.5, 29.88, 15.0)
    # wash bay, valet store
    car(b, 35.5, 5.0, 0)
    b.box(38.2, 6.8, 38.88, 7.7); b.box(33.12, 11.3, 38.88, 11.88); b.table(33.5, 9.0, 34.7, 9.8)
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(2.0, 2.0), (14.0, 6.5)], speed=0.12)
    b.person([(19.5, 4.5), (27.0, 4.5)], speed=0.1, start=200)
    b.space(8.0, 6.5, "room", "showroom", region=(0.6, 0.6, 15.4, 11.4))
    b.space(3.0, 14.0, "room", "customer lounge", region=(1.0, 12.6, 5.4, 16.8))
    b.space(8.0, 13.8, "room", "sales office 1", region=(6.6, 12.6, 9.4, 15.5))
    b.space(12.0, 13.6, "room", "sales office 2", region=(10.6, 12.6, 13.4, 15.5))
    b.space(15.0, 14.6, "room", "customer WC", region=(14.5, 12.6, 15.4, 17.0))
    b.space(24.0, 7.0, "room", "workshop", group="workshop", region=(16.6, 3.2, 29.2, 11.4))
    b.space(24.0, 15.0, "room", "workshop tyre alcove", group="workshop", region=(22.8, 12.6, 25.2, 17.0))
    b.space(21.0, 15.0, "room", "parts store", region=(20.3, 12.6, 21.5, 17.4))
    b.space(28.0, 14.5, "room", "workshop office", region=(26.6, 12.6, 29.0, 16.0))
    b.space(35.5, 3.0, "room", "wash bay", region=(33.6, 2.6, 38.4, 7.4))
    b.space(36.5, 9.9, "room", "valet store", region=(35.0, 8.6, 38.4, 11.0))
    T = b.tour
    T([(8.0, 0.8), (8.0, 2.0), (1.5, 1.5), (1.2, 7.0), (3.0, 11.0), (3.0, 14.0), (1.8, 13.0), (4.8, 13.0), (3.0, 14.0),
       (3.0, 11.0), (8.0, 11.0), (8.0, 13.8), (8.0, 11.0), (12.0, 11.0), (12.0, 13.6), (12.0, 11.0), (15.0, 11.0),
       (15.0, 14.6), (15.0, 11.0), (10.0, 6.5), (15.0, 6.0), (17.0, 6.0), (19.5, 4.3), (27.0, 4.3), (28.8, 1.2),
       (24.0, 1.0), (18.5, 1.0), (17.0, 4.0), (22.0, 7.0), (28.2, 8.0), (28.2, 11.0), (24.0, 11.0), (24.0, 15.0),
       (24.0, 11.0), (19.0, 11.0), (19.0, 12.9), (21.0, 12.9), (21.0, 17.3), (21.0, 15.75),
       (16.6, 15.75), (16.6, 14.35), (21.0, 14.35), (21.0, 12.9), (19.0, 12.9), (19.0, 11.0), (28.0, 11.0),
       (28.0, 14.5), (28.0, 11.0), (22.0, 9.0), (17.0, 6.0), (15.0, 6.0), (8.0, 2.0), (8.0, 0.8)])
    T([(8.0, 0.8), (8.0, 2.0), (14.0, 7.0), (17.0, 6.0), (25.0, 6.5), (28.5, 10.5), (22.0, 10.5), (17.0, 6.0),
       (9.0, 11.0), (2.0, 6.0), (8.0, 0.8)], bias=(0.05, 0.07, 0.45))
    T([(38.2, 5.0), (38.2, 3.0), (34.0, 3.0), (34.0, 7.0), (37.0, 7.0), (37.0, 9.5), (34.8, 10.4), (37.8, 10.4),
       (37.0, 9.5), (37.0, 7.0), (38.2, 6.2), (38.2, 5.0)])
    return b


# ----------------------------------------------------------------------------------------------
def studio():
    b = B("b9_recording_studio", "Recording studio (24 x 14 m, rotated 152 deg, 0.05 m cells, front-facing 270 deg "
          "lidar). Reception (1.0 m street door; 1.4 m opening onto the corridor), a 1.8 m corridor (one hallway; "
          "flight cases; 1.0 m fire exit); south: control room A (0.9 m; a console in front of the studio window "
          "leaving a 0.65 m squeeze = passage) with a 0.9 m door into live room A (1.4 m double door from the "
          "corridor; grand piano, drum kit, a line of acoustic screens with a 0.8 m gap = passage) and two vocal "
          "booths off it (0.8 m doors), a machine room (0.9 m); north: a lounge (1.6 m arch), control room B (0.9 m) "
          "with a door into live room B (1.2 m from the corridor), a WC (0.8 m) and an edit suite (0.9 m, seen only "
          "through its door). Two musicians. Hard: thick studio walls with windows between rooms, small booths, "
          "rooms reached through rooms, 270 deg lidar.", (24, 14), theta=152, seed=56, margin=7.0, res=0.05, fov=270.0)
    w = b.wall
    w((0, 0), (24, 0), EXT, doors=[(2.5, 1.0, "reception street door (to outside)", ("a", 1, 90))])
    w((24, 0), (24, 14), EXT, doors=[(6.9, 1.0, "corridor east fire exit (to outside)", ("b", -1, 85))])
    w((24, 14), (0, 14), EXT, windows=[(18.0, 22.5)])
    w((0, 14), (0, 0), EXT)
    w((0, 6), (24, 6), 0.2, doors=[(2.5, 1.4, "reception to corridor (opening)", None),
                                   (7.5, 0.9, "corridor to control room A", ("a", -1, 90)),
                                   (14.0, 1.4, "corridor to live room A (double door)", ("d", -1, 90)),
                                   (22.75, 0.9, "corridor to machine room", ("b", -1, 90))])
    w((0, 7.8), (24, 7.8), 0.2, doors=[(3.5, 1.6, "corridor to lounge (arch)", None),
                                       (9.0, 0.9, "corridor to control room B", ("a", 1, 90)),
                                       (14.0, 1.2, "corridor to live room B", ("b", 1, 90)),
                                       (18.25, 0.8, "corridor to WC", ("a", 1, 90)),
                                       (21.75, 0.9, "corridor to edit suite", ("b", 1, 90))])
    w((5, 0), (5, 6), 0.2)
    w((10, 0), (10, 6), 0.3, doors=[(4.9, 0.9, "control room A to live room A", ("a", -1, 90))], windows=[(1.2, 3.8)])
    w((19, 0), (19, 6), 0.2, doors=[(1.5, 0.8, "live room A to vocal booth 1", ("a", -1, 90)),
                                    (4.5, 0.8, "live room A to vocal booth 2", ("b", -1, 90))])
    w((19, 3), (21.5, 3), 0.2); w((21.5, 0), (21.5, 6), 0.2)
    w((7, 7.8), (7, 14), 0.2)
    w((11, 7.8), (11, 14), 0.3, doors=[(5.3, 0.9, "control room B to live room B", ("a", -1, 90))], windows=[(1.2, 3.7)])
    w((17, 7.8), (17, 14), 0.2); w((19.5, 7.8), (19.5, 14), 0.2)
    # reception
    b.box(0.12, 3.6, 1.8, 4.2); b.box(3.6, 0.8, 4.9, 2.6)
    # control room A: console in front of the window, sofa at the back
    b.box(8.3, 1.0, 9.2, 4.3)
    b.passage(9.525, 2.65, 0.65, "control room A: squeeze between the console and the studio window", across=(1, 0))
    b.box(5.1, 1.0, 5.7, 4.0)
    b.dot(8.0, 0.5, 0.08); b.dot(8.0, 4.8, 0.08)
    # live room A
    b.rbox(12.6, 1.5, 2.2, 1.4, 8)                               # grand piano
    b.seg((12.0, 3.4), (14.6, 3.4), 0.08); b.seg((15.4, 3.4), (17.5, 3.4), 0.08)   # acoustic screens
    b.passage(15.0, 3.4, 0.8, "live room A: gap in the line of acoustic screens", across=(1, 0))
    for a in range(0, 360, 60):
        b.dot(17.2 + 0.6 * math.cos(math.radians(a)), 1.6 + 0.6 * math.sin(math.radians(a)), 0.12)   # drum kit
    b.box(11.0, 5.2, 11.8, 5.85)
    # booths, machine room
    b.box(21.0, 0.2, 21.35, 0.6); b.box(21.0, 5.4, 21.35, 5.8)
    b.box(23.2, 0.5, 23.88, 4.6)
    # lounge, control B, live B, WC, edit suite
    b.box(0.12, 8.5, 0.7, 12.0); b.box(2.0, 13.2, 5.0, 13.88); b.table(3.5, 10.0, 4.5, 11.0)
    b.box(8.8, 9.5, 9.6, 12.5); b.box(7.1, 12.8, 7.7, 13.9)
    for a in range(0, 360, 60):
        b.dot(14.0 + 0.6 * math.cos(math.radians(a)), 12.2 + 0.6 * math.sin(math.radians(a)), 0.12)
    b.box(16.0, 8.0, 16.9, 8.9); b.box(11.15, 8.0, 12.0, 8.8)
    b.box(17.1, 13.2, 17.6, 13.9); b.box(19.0, 11.5, 19.4, 12.0)
    b.desk(20.0, 13.0, 23.5, 13.9, "n"); b.chair(21.5, 12.5)
    b.box(15.0, 7.3, 16.2, 7.7)                                  # flight cases in the corridor
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(3.0, 9.5), (5.5, 12.5)], speed=0.08)
    b.person([(13.5, 4.6)], start=0, stop=900)
    b.space(2.6, 2.2, "room", "reception", region=(0.6, 0.6, 3.4, 5.4))
    b.space(12.0, 6.9, "hallway", "corridor", region=(0.6, 6.4, 23.4, 7.4))
    b.space(7.0, 3.0, "room", "control room A", region=(5.9, 0.6, 8.0, 5.4))
    b.space(15.8, 4.6, "room", "live room A", region=(10.6, 0.6, 18.4, 5.4))
    b.space(20.3, 1.9, "room", "vocal booth 1", region=(19.6, 0.7, 20.9, 2.5))
    b.space(20.3, 4.1, "room", "vocal booth 2", region=(19.6, 3.5, 20.9, 5.3))
    b.space(22.4, 3.0, "room", "machine room", region=(21.9, 0.6, 22.9, 5.4))
    b.space(3.5, 9.5, "room", "lounge", region=(1.0, 8.4, 6.4, 13.0))
    b.space(8.0, 11.0, "room", "control room B", region=(7.5, 8.4, 8.5, 12.5))
    b.space(14.0, 10.2, "room", "live room B", region=(11.6, 8.4, 16.4, 13.4))
    b.space(18.25, 11.0, "room", "WC", region=(17.6, 8.6, 18.9, 13.0))
    b.space(21.75, 10.5, "room", "edit suite", region=(20.1, 8.4, 23.4, 12.4))
    T = b.tour
    T([(2.5, 1.2), (2.5, 2.8), (1.0, 2.5), (1.0, 5.0), (2.5, 5.0), (2.5, 6.9), (7.5, 6.9), (7.5, 5.0), (6.2, 4.6),
       (6.2, 0.6), (9.525, 0.6), (9.525, 4.7), (10.8, 4.9), (13.0, 4.6), (15.0, 4.6), (15.0, 2.5), (11.2, 3.0),
       (15.0, 2.5), (18.55, 2.5), (18.55, 1.5), (20.3, 1.8), (18.55, 1.5), (18.55, 4.5), (20.3, 4.1), (18.55, 4.5),
       (15.0, 4.9), (14.0, 4.9), (14.0, 6.9), (22.75, 6.9), (22.75, 3.0), (22.75, 6.9), (23.3, 6.9), (9.0, 6.9),
       (9.0, 8.5), (8.0, 11.0), (8.2, 12.9), (10.5, 13.1), (12.0, 13.1), (14.0, 10.2), (15.5, 12.0),
       (14.0, 9.0), (14.0, 6.9), (18.25, 6.9), (18.25, 9.0), (18.25, 6.9), (21.75, 6.9), (3.5, 6.9), (3.5, 9.0),
       (1.5, 12.8), (5.5, 12.0), (6.0, 9.0), (3.5, 8.5), (3.5, 6.9), (2.5, 6.9), (2.5, 2.8), (2.5, 1.2)])
    T([(2.5, 1.2), (2.5, 6.9), (20.0, 6.9), (14.0, 6.9), (14.0, 4.8), (17.5, 4.8), (14.0, 4.8), (14.0, 6.9),
       (2.5, 6.9), (2.5, 1.2)], bias=(-0.06, -0.05, 0.5))
    return b


BUILDINGS = [airport, print_shop, bakery, town_hall, car_dealership, studio]
