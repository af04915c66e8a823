"""The blind8 buildings (building frame: u east, v north, metres). See README.md.
Routes are planned through listed stops with B.tour (blind8)."""
import math

from sim import B

EXT = 0.24


def bed(b, u0, v0, u1, v1):
    b.box(u0, v0, u1, v1)


def wheelchair(b, u, v, ang):
    """Two big wheels (thin plates) and two casters."""
    a = math.radians(ang)
    c, s = math.cos(a), math.sin(a)
    def P(x, y):
        return (u + c * x - s * y, v + s * x + c * y)
    for y in (-0.3, 0.3):
        b.seg(P(-0.3, y), P(0.25, y), 0.04)
    for y in (-0.22, 0.22):
        b.dot(*P(0.45, y), 0.03)


# ----------------------------------------------------------------------------------------------
def nursing_home():
    b = B("b8_nursing_home", "Nursing home wing (36 x 18 m, rotated 24 deg, 0.05 m cells): a 2.4 m care corridor the "
          "whole length of the wing (one hallway; wheelchairs, a linen trolley and a medicine cart parked along it); "
          "south: four resident rooms with en-suite bathrooms (1.1 m bed-width doors, 0.9 m bathroom doors), a dining "
          "room (1.6 m double door; tables, a sideboard and a piano leaving a 0.75 m squeeze), a servery kitchen and a "
          "lounge (1.6 m double door; two back-to-back sofas leave a 0.8 m gap to the conservatory corner); north: four "
          "resident rooms (two seen only through their doors), nurses' station, assisted bathroom, sluice room, "
          "activity room. Residents and carers walking. Hard: many small rooms, en-suites seen only through doors, "
          "clutter in the corridor.", (36, 18), theta=24, seed=41, margin=8.0, res=0.05)
    w = b.wall
    w((0, 0), (36, 0), EXT, windows=[(1.0, 2.6), (4.6, 6.2), (8.2, 9.8), (11.8, 13.4), (16.0, 22.0), (29.5, 34.5)])
    w((36, 0), (36, 18), EXT, doors=[(9.2, 1.6, "care corridor east end double door (to outside / main house)", ("d", -1, 85))])
    w((36, 18), (0, 18), EXT, windows=[(2.0, 4.0), (20.0, 24.0)])
    w((0, 18), (0, 0), EXT, doors=[(8.8, 1.2, "care corridor west fire exit (to outside)", ("a", 1, 80))])
    # corridor v 8..10.4
    w((0, 8), (36, 8), doors=[(2.8, 1.1, "corridor to resident room S1", ("b", -1, 88)),
                              (6.4, 1.1, "corridor to resident room S2", ("b", -1, 92)),
                              (10.0, 1.1, "corridor to resident room S3", ("b", -1, 85)),
                              (13.6, 1.1, "corridor to resident room S4", ("b", -1, 90)),
                              (17.0, 1.6, "corridor to dining room (double door)", ("d", -1, 88)),
                              (25.2, 0.9, "corridor to servery kitchen", ("a", -1, 90)),
                              (31.0, 1.6, "corridor to lounge (double door)", ("d", -1, 90))])
    w((0, 10.4), (36, 10.4), doors=[(2.8, 1.1, "corridor to resident room N1", ("b", 1, 90)),
                                    (6.4, 1.1, "corridor to resident room N2", ("b", 1, 80)),
                                    (10.0, 1.1, "corridor to resident room N3", ("b", 1, 90)),
                                    (13.6, 1.1, "corridor to resident room N4", ("b", 1, 95)),
                                    (16.2, 1.0, "corridor to nurses' station", ("a", 1, 90)),
                                    (20.6, 1.2, "corridor to assisted bathroom", ("a", 1, 90)),
                                    (23.7, 0.9, "corridor to sluice room", ("b", 1, 90)),
                                    (28.0, 1.6, "corridor to activity room (double door)", ("d", 1, 90))])
    # south rooms 0..14.4 (3.6 m each), en-suite in the corridor-side west corner
    for k in range(4):
        u0 = 3.6 * k
        w((u0 + 3.6, 0), (u0 + 3.6, 8))
        w((u0, 5.6), (u0 + 2.1, 5.6), doors=[(1.05, 0.9, f"resident room S{k+1} to en-suite", ("a", -1, 85))])
        w((u0 + 2.1, 5.6), (u0 + 2.1, 8))
        b.box(u0 + 0.14, 7.2, u0 + 0.6, 7.86)                          # wc
        b.box(u0 + 1.5, 6.6, u0 + 2.0, 7.3)                            # basin
        bed(b, u0 + 0.3, 1.2, u0 + 1.3, 3.3)
        b.box(u0 + 0.15, 3.45, u0 + 0.6, 3.9)                          # nightstand
        b.box(u0 + 2.9, 0.2, u0 + 3.5, 1.4)                            # wardrobe
        b.chair(u0 + 2.6, 3.2)
        b.space(u0 + 2.1, 4.4, "room", f"resident room S{k+1}", region=(u0 + 0.3, 0.3, u0 + 3.4, 5.4))
        b.space(u0 + 0.9, 6.5, "room", f"en-suite S{k+1}", region=(u0 + 0.2, 5.8, u0 + 2.0, 7.9))
    w((24, 0), (24, 8), doors=[(6.5, 0.9, "dining room to servery kitchen", ("b", 1, 90))])
    w((28, 0), (28, 8))
    # dining room 14.4..24
    for (u0, v0) in [(15.5, 1.4), (18.4, 1.4), (21.3, 1.4), (15.5, 4.3), (18.4, 4.3)]:
        b.table(u0, v0, u0 + 1.4, v0 + 0.9)
        for du in (0.35, 1.05):
            b.chair(u0 + du, v0 - 0.35); b.chair(u0 + du, v0 + 1.25)
    b.box(22.4, 4.6, 23.19, 6.2)                                     # piano, 0.75 m off the east wall
    b.passage(23.565, 5.4, 0.75, "dining room: squeeze between the piano and the east wall", across=(1, 0))
    # servery kitchen 24..28
    b.box(24.06, 0.12, 27.94, 0.75); b.box(27.3, 0.75, 27.94, 5.0); b.box(24.8, 2.6, 26.4, 3.4)
    # lounge 28..36
    b.box(30.0, 3.5, 33.2, 4.4)                                      # back-to-back sofas
    b.box(28.06, 3.5, 28.7, 4.4)                                     # bookcase -> 0.8 m gap to the sofas... not a passage
    b.box(34.0, 3.6, 35.88, 4.3)                                # armchair block, leaves 0.8 m
    b.passage(33.6, 3.95, 0.8, "lounge: gap between the sofas and the armchairs (to the conservatory corner)", across=(1, 0))
    b.box(28.06, 6.0, 28.5, 7.88); b.box(35.2, 6.5, 35.88, 7.88)
    b.table(31.0, 1.0, 32.4, 2.0)
    # north rooms 0..14.4
    for k in range(4):
        u0 = 3.6 * k
        w((u0 + 3.6, 10.4), (u0 + 3.6, 18))
        w((u0 + 2.1, 12.8), (u0, 12.8), doors=[(1.05, 0.9, f"resident room N{k+1} to en-suite", ("b", -1, 85))])
        w((u0 + 2.1, 10.4), (u0 + 2.1, 12.8))
        b.box(u0 + 0.14, 10.54, u0 + 0.6, 11.2); b.box(u0 + 1.5, 11.1, u0 + 2.0, 11.8)
        bed(b, u0 + 0.3, 15.1, u0 + 1.3, 17.2)
        b.box(u0 + 0.15, 14.5, u0 + 0.6, 14.95)
        b.box(u0 + 2.9, 16.6, u0 + 3.5, 17.86)
        b.chair(u0 + 2.6, 15.2)
        b.space(u0 + 2.1, 14.0, "room", f"resident room N{k+1}", region=(u0 + 0.3, 13.0, u0 + 3.4, 17.8))
        if k >= 2:
            b.space(u0 + 0.9, 11.8, "room", f"en-suite N{k+1}", region=(u0 + 0.2, 10.5, u0 + 2.0, 12.6))
    w((18.8, 10.4), (18.8, 18)); w((22.4, 10.4), (22.4, 18)); w((25.0, 10.4), (25.0, 18))
    # nurses' station 14.4..18.8
    b.desk(14.6, 14.0, 16.6, 14.8, "n"); b.desk(17.2, 11.8, 18.6, 13.6, "e"); b.chair(15.6, 13.5); b.chair(16.8, 12.6)
    b.box(14.54, 16.8, 16.5, 17.86)
    b.clutter((14.4, 17.88), (18.8, 17.88), -1, 2, depth=(0.3, 0.5))
    # assisted bathroom 18.8..22.4: hoist bath in the middle
    b.box(19.6, 14.4, 21.6, 15.4); b.box(21.7, 10.54, 22.28, 11.2)
    # sluice 22.4..25
    b.box(22.54, 15.5, 24.88, 17.86); b.box(24.2, 11.0, 24.88, 13.5)
    # activity room 25..36
    for (u0, v0) in [(27.0, 13.0), (30.5, 13.0), (27.0, 15.6)]:
        b.table(u0, v0, u0 + 1.8, v0 + 0.9)
        b.chair(u0 + 0.5, v0 - 0.35); b.chair(u0 + 1.3, v0 - 0.35); b.chair(u0 + 0.5, v0 + 1.25)
    b.clutter((25.12, 17.88), (36, 17.88), -1, 4)
    b.box(34.6, 11.0, 35.88, 12.2)
    # corridor clutter (against the walls, outside the door swings)
    wheelchair(b, 4.6, 8.55, 0); wheelchair(b, 18.0, 9.85, 180)
    b.box(8.2, 9.55, 9.0, 10.28)                                     # linen trolley
    b.box(26.5, 8.12, 27.3, 8.62)                                    # medicine cart
    b.box(33.5, 9.8, 34.9, 10.28)                                    # bench
    b.outside(10, dmin=1.5, dmax=6.0)
    # people
    b.person([(5.0, 9.2), (30.0, 9.2)], speed=0.15)
    b.person([(19.5, 3.2)], start=0, stop=900)
    b.person([(30.5, 6.0), (34.5, 6.5)], speed=0.1, start=300)
    # other spaces
    b.space(18.0, 9.2, "hallway", "care corridor", region=(0.5, 8.3, 35.5, 10.1))
    b.space(20.8, 5.6, "room", "dining room", region=(14.6, 0.3, 23.8, 7.8))
    b.space(25.8, 5.5, "room", "servery kitchen", region=(24.2, 1.0, 27.2, 7.8))
    b.space(32.0, 6.0, "room", "lounge", region=(28.6, 0.3, 35.7, 7.8))
    b.space(15.3, 12.4, "room", "nurses' station", region=(14.6, 10.6, 18.6, 16.6))
    b.space(20.6, 12.5, "room", "assisted bathroom", region=(19.0, 10.6, 22.2, 17.8))
    b.space(23.7, 13.8, "room", "sluice room", region=(22.6, 10.6, 24.8, 15.4))
    b.space(30.5, 11.6, "room", "activity room", region=(25.2, 10.6, 35.7, 17.6))
    T = b.tour
    stops = [(35.0, 9.2), (31.0, 9.2), (31.0, 6.0), (34.5, 5.5), (33.6, 3.95), (34.8, 2.0), (29.0, 2.0), (29.0, 6.5),
             (31.0, 7.0), (31.0, 9.2), (28.0, 9.2), (28.0, 11.5), (33.5, 11.6), (33.5, 16.6), (26.0, 16.6), (26.0, 12.0),
             (28.0, 11.5), (28.0, 9.2), (25.2, 9.2), (25.2, 6.5), (26.0, 1.8), (25.2, 6.5), (23.5, 6.5), (23.565, 4.0),
             (23.5, 1.0), (17.65, 0.6), (17.65, 3.3), (20.8, 5.6), (17.0, 7.0), (17.0, 9.2), (16.2, 9.2), (16.2, 12.0),
             (16.2, 9.2), (20.6, 9.2), (20.6, 12.0), (20.6, 9.2)]
    for k in (3, 2, 1, 0):
        u0 = 3.6 * k
        stops += [(u0 + 2.8, 9.2), (u0 + 2.8, 6.5), (u0 + 2.1, 4.2), (u0 + 2.2, 1.0), (u0 + 2.1, 4.2), (u0 + 2.8, 6.5),
                  (u0 + 2.8, 9.2)]
    T(stops + [(0.8, 9.2)])
    T([(0.8, 9.2), (10.0, 9.2), (10.0, 12.0), (10.7, 15.2), (10.0, 12.0), (13.6, 12.0), (14.2, 15.5), (13.6, 12.0),
       (13.6, 9.2), (35.0, 9.2)], bias=(0.07, -0.05, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def police_station():
    b = B("b8_police_station", "Police station (32 x 21 m, axis-aligned, 0.1 m cells): public entrance lobby (1.6 m "
          "entrance double door, benches) with a glass enquiry screen and a 0.9 m glass door into the front office; a "
          "2 m main corridor along the building and a 1.8 m side corridor going north (one hallway); CID open office "
          "(desk clusters; 1.6 m double door and a 0.9 m door), commander's office; custody suite (1.2 m secure door, "
          "custody desk) with a 1.0 m door into a cell corridor (second hallway) and five cells (0.8 m doors, two "
          "closed), two interview rooms, an evidence store with shelving aisles (0.8 m = passages), a locker room "
          "with a locker island, and a sally port garage with a patrol car. Officers walking. Hard: coarse cells "
          "(0.8 m doors are 8 cells), glass front, small cells seen only through their doors.",
          (32, 21), theta=0, seed=42, margin=8.0, res=0.1)
    w = b.wall
    w((0, 0), (32, 0), EXT, doors=[(4.0, 1.6, "main entrance double door (lobby to outside)", ("d", 1, 80))],
      windows=[(9.0, 13.0), (16.0, 25.0), (27.0, 31.0)])
    w((32, 0), (32, 21), EXT, doors=[(8.0, 1.0, "main corridor east fire exit (to outside)", ("a", -1, 90))])
    w((32, 21), (0, 21), EXT, doors=[(11.0, 1.0, "side corridor north door (to the yard)", ("b", -1, 85))])
    w((0, 21), (0, 0), EXT)
    # main corridor v 7..9
    w((0, 7), (32, 7), doors=[(6.5, 1.0, "lobby to main corridor (secure door)", ("a", 1, 90)),
                              (12.5, 0.9, "main corridor to front office", ("b", -1, 90)),
                              (17.0, 1.6, "main corridor to CID office (double door)", ("d", -1, 90)),
                              (24.0, 0.9, "main corridor to CID office", ("a", -1, 90)),
                              (28.0, 0.9, "main corridor to commander's office", ("a", -1, 90))])
    w((8, 0), (8, 7), glass=True, doors=[(3.5, 0.9, "lobby to front office (glass door)", ("a", -1, 90))])
    b.box(7.5, 0.8, 7.9, 3.0); b.box(7.5, 4.0, 7.9, 6.2)              # enquiry counter on the lobby side
    w((14, 0), (14, 7)); w((26, 0), (26, 7))
    w((0, 9), (20, 9), doors=[(10.0, 1.2, "main corridor to custody suite (secure door)", ("a", 1, 90)),
                              (15.5, 0.9, "main corridor to interview room 1", ("b", 1, 90)),
                              (18.5, 0.9, "main corridor to interview room 2", ("a", 1, 90))])
    w((22, 9), (32, 9), doors=[(5.0, 1.0, "main corridor to locker room", ("a", 1, 90))])
    # side corridor u 20..22, v 9..21
    w((20, 9), (20, 21), doors=[(7.5, 1.0, "side corridor to evidence store", None)])
    w((22, 9), (22, 21), doors=[(8.5, 1.2, "side corridor to sally port", ("a", -1, 90))])
    w((22, 13), (32, 13))
    # custody 0..14, 9..15; cell corridor 15..17; cells 17..21
    w((0, 15), (14, 15), doors=[(11.5, 1.0, "custody suite to cell corridor", ("b", -1, 90))])
    w((0, 17), (14, 17), doors=[(1.4, 0.8, "cell corridor to cell 1", ("a", -1, 90)),
                               (4.2, 0.8, "cell corridor to cell 2", ("a", -1, 90)),
                               {"at": 7.0, "w": 0.8, "note": "cell 3 (closed)", "closed": True},
                               (9.8, 0.8, "cell corridor to cell 4", ("a", -1, 90)),
                               {"at": 12.6, "w": 0.8, "note": "cell 5 (closed)", "closed": True}])
    for k in range(1, 5):
        w((2.8 * k, 17), (2.8 * k, 21), 0.2)
    w((14, 9), (14, 21)); w((17, 9), (17, 13)); w((14, 13), (20, 13))
    for k, u0 in enumerate((0.0, 2.8, 8.4)):
        b.box(u0 + 0.15, 19.6, u0 + 2.0, 20.85)                      # bench bed
    # lobby
    b.box(0.12, 2.0, 0.6, 5.5); b.box(2.0, 6.3, 5.0, 6.88)
    for u in (2.5, 3.5, 4.5):
        b.dot(u, 3.5, 0.03)
    # front office
    b.desk(8.3, 4.5, 10.0, 5.3, "w"); b.desk(11.5, 0.3, 13.2, 1.0, "s"); b.chair(9.1, 4.0); b.chair(12.4, 1.5)
    b.box(13.3, 3.0, 13.88, 6.0)
    # CID open office: four desk clusters
    for (u0, v0) in [(15.5, 1.2), (19.5, 1.2), (15.5, 4.2), (19.5, 4.2)]:
        b.desk(u0, v0, u0 + 2.8, v0 + 0.8, "n"); b.desk(u0, v0 + 0.8, u0 + 2.8, v0 + 1.6, None)
        for du in (0.7, 2.1):
            b.chair(u0 + du, v0 - 0.4); b.chair(u0 + du, v0 + 2.0)
    b.clutter((14.12, 0.12), (25.88, 0.12), 1, 0)
    b.box(23.6, 2.0, 25.88, 2.6); b.box(25.3, 3.2, 25.88, 6.2)
    # commander
    b.desk(27.2, 2.0, 29.0, 2.9, "s"); b.chair(28.0, 3.4); b.table(29.8, 4.4, 31.4, 5.6); b.box(31.3, 0.2, 31.88, 2.0)
    # custody desk (counter island)
    b.box(4.0, 11.2, 9.0, 12.0); b.box(0.12, 9.2, 0.6, 13.5); b.box(12.4, 13.8, 13.88, 14.88)
    # interview rooms
    for u0 in (14.0, 17.0):
        b.table(u0 + 0.8, 10.8, u0 + 2.2, 11.6); b.chair(u0 + 1.5, 10.3, 0); b.chair(u0 + 1.5, 12.1, 0)
    # evidence store 14..20, 13..21: shelving rows E-W, 0.8 m aisles, cross aisle at the door side
    for v0 in (14.2, 15.8, 17.4, 19.0):
        b.box(14.12, v0, 18.4, v0 + 0.8)
    b.passage(16.2, 15.4, 0.8, "evidence store: aisle between shelving rows 1 and 2", across=(0, 1))
    b.passage(16.2, 17.0, 0.8, "evidence store: aisle between shelving rows 2 and 3", across=(0, 1))
    b.passage(16.2, 18.6, 0.8, "evidence store: aisle between shelving rows 3 and 4", across=(0, 1))
    # locker room 22..32, 9..13: wall lockers north + locker island -> 0.85 m aisle
    b.box(22.5, 12.4, 29.5, 12.88); b.box(23.5, 10.95, 28.5, 11.55)
    b.passage(26.0, 11.98, 0.85, "locker room: aisle between the wall lockers and the locker island", across=(0, 1))
    b.box(31.2, 9.12, 31.88, 12.88)
    # sally port 22..32, 13..21: patrol car, closed roller door (wall), workbench
    b.rbox(27.5, 17.0, 4.6, 1.8, 3); b.box(30.8, 13.12, 31.88, 15.0); b.box(22.12, 19.5, 24.5, 20.88)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(2.0, 8.0), (30.0, 8.0)], speed=0.2)
    b.person([(6.0, 12.6)], start=0, stop=1400)
    b.person([(18.9, 0.7)], start=500)
    b.space(3.5, 3.5, "room", "entrance lobby", region=(0.8, 0.5, 7.3, 6.2))
    b.space(11.0, 3.0, "room", "front office", region=(8.3, 0.5, 13.2, 6.8))
    b.space(20.0, 3.0, "room", "CID office", region=(14.3, 0.3, 25.7, 6.8))
    b.space(29.5, 3.5, "room", "commander's office", region=(26.3, 0.3, 31.7, 6.8))
    b.space(16.0, 8.0, "hallway", "main corridor + side corridor", region=(0.5, 7.2, 31.5, 8.8))
    b.space(6.0, 13.5, "room", "custody suite", region=(0.8, 9.2, 13.8, 14.8))
    b.space(7.0, 16.0, "hallway", "cell corridor", region=(0.5, 15.2, 13.5, 16.8))
    for k in (0, 1, 3):
        b.space(2.8 * k + 1.4, 18.6, "room", f"cell {k + 1}", region=(2.8 * k + 0.2, 17.2, 2.8 * k + 2.6, 19.5))
    b.space(15.5, 11.5, "room", "interview room 1", region=(14.2, 9.2, 16.8, 12.8))
    b.space(18.5, 11.5, "room", "interview room 2", region=(17.2, 9.2, 19.8, 12.8))
    b.space(19.17, 16.0, "room", "evidence store", region=(18.45, 13.2, 19.9, 20.8))
    b.space(24.5, 10.2, "room", "locker room", region=(22.2, 9.2, 31.0, 10.9))
    b.space(26.0, 14.5, "room", "sally port garage", region=(22.2, 13.2, 31.8, 20.8))
    T = b.tour
    T([(4.0, 1.0), (4.0, 4.6), (6.5, 5.0), (7.0, 3.5), (9.0, 3.5), (11.0, 2.8), (12.5, 5.6), (12.5, 8.0), (6.5, 8.0),
       (1.0, 8.0), (10.0, 8.0), (10.0, 10.0), (3.0, 10.3), (2.0, 13.8), (10.0, 13.0), (11.5, 14.0), (11.5, 16.0), (9.8, 16.0),
       (9.8, 18.5), (9.8, 16.0), (4.2, 16.0), (4.2, 18.6), (4.2, 16.0), (1.4, 16.0), (1.4, 18.6), (1.4, 16.0), (13.2, 16.0),
       (11.5, 14.0), (10.0, 10.0), (10.0, 8.0), (15.5, 8.0), (15.5, 11.0), (15.5, 8.0), (18.5, 8.0), (18.5, 10.5), (18.5, 8.0),
       (21.0, 8.0), (21.0, 16.5), (19.3, 16.5), (18.9, 15.4), (18.9, 18.6), (19.3, 16.5), (21.0, 16.5), (21.0, 17.5),
       (23.5, 17.5), (24.0, 14.2), (31.0, 16.0), (30.5, 19.8), (24.8, 19.6), (23.5, 17.5), (21.0, 17.5), (21.0, 20.4),
       (21.0, 8.0), (27.0, 8.0), (27.0, 10.0), (30.5, 10.0), (23.0, 10.0), (22.6, 11.98), (29.2, 11.98), (30.5, 10.5),
       (27.0, 10.0), (27.0, 8.0), (31.5, 8.0)])
    T([(31.5, 8.0), (28.0, 8.0), (28.0, 4.0), (30.5, 3.6), (28.0, 4.0), (28.0, 8.0), (24.0, 8.0), (24.0, 3.4), (19.0, 3.4),
       (14.8, 3.6), (17.0, 6.4), (17.0, 8.0), (4.0, 8.0)], bias=(-0.06, 0.08, -0.55))
    return b


# ----------------------------------------------------------------------------------------------
def data_centre():
    b = B("b8_data_centre", "Server room floor / small data centre (22 x 15 m, rotated -17 deg, 0.025 m cells): "
          "security lobby (1.2 m entrance door) with a glass wall and glass door onto a 2 m service corridor (one "
          "hallway); network operations centre (NOC; 0.9 m door; a video wall and desks), build / staging room "
          "(1.8 m loading double door to outside, 1.2 m door to the corridor; pallets, crates); data hall (1.6 m "
          "double door; seven rack rows, hot / cold aisles of 0.9 m (= passages) and 1.2 m, a cross-over gap in two "
          "rows, cooling units along the east wall); UPS room (1.0 m) and a battery room behind it (1.0 m; battery "
          "racks with 0.8 m aisles = passages). Two technicians. Hard: fine cells, rack rows that map like walls, "
          "narrow aisles that are NOT doors.", (22, 15), theta=-17, seed=43, margin=7.0, res=0.025)
    w = b.wall
    w((0, 0), (22, 0), EXT, doors=[(3.0, 1.2, "entrance door (security lobby to outside)", ("a", 1, 90))])
    w((22, 0), (22, 15), EXT)
    w((22, 15), (0, 15), EXT, doors=[(19.0, 1.8, "staging room loading double door (to outside)", ("d", -1, 85))])
    w((0, 15), (0, 0), EXT, windows=[(5.0, 8.0)])
    # corridor u 6..8
    w((6, 0), (6, 15), glass=False, doors=[(2.0, 0.9, "security lobby to corridor", ("a", 1, 90)),
                                           (6.5, 0.9, "corridor to NOC", ("b", 1, 90)),
                                           (12.0, 1.2, "corridor to staging room", ("a", 1, 90))])
    w((8, 0), (8, 15), 0.2, doors=[(5.0, 1.6, "corridor to data hall (double door)", ("d", -1, 90)),
                                   (12.5, 1.0, "corridor to UPS room", ("b", -1, 90))])
    w((0, 4), (6, 4), glass=True, doors=[(4.4, 0.9, "security lobby to NOC (glass door)", ("a", 1, 90))])
    w((0, 9), (6, 9))
    w((8, 10), (22, 10), 0.2)
    w((15, 10), (15, 15), doors=[(2.5, 1.0, "UPS room to battery room", ("a", -1, 90))])
    # lobby: desk, turnstile-free; bench
    b.box(0.5, 0.12, 2.2, 0.7); b.box(3.8, 2.6, 5.0, 3.2); b.box(0.12, 1.2, 0.5, 3.5)
    # NOC: video wall on the west, desk rows
    b.box(0.12, 4.6, 0.45, 8.4)
    b.desk(1.8, 5.2, 4.2, 6.0, "w"); b.desk(1.8, 7.0, 4.2, 7.8, "w")
    for u in (2.5, 3.9):
        b.chair(u, 6.4); b.chair(u, 8.2)
    # staging: pallets, crates, workbench
    b.box(0.6, 13.0, 1.8, 14.0); b.box(4.2, 13.0, 5.2, 14.2); b.box(0.12, 9.2, 0.7, 11.8); b.box(4.0, 9.6, 5.88, 10.3)
    # data hall 8..22 x 0..10: rack rows E-W, u 10..19, depth 0.6
    rows = [1.2, 2.7, 3.9, 5.4, 6.6, 8.1]       # row south faces; aisles between: 0.9, 0.6?, ...
    # row k occupies v0..v0+0.6; aisles: 1.8-2.7 = 0.9, 3.3-3.9 = 0.6 (hot, too tight -> not annotated?)
    rows = [0.9, 2.4, 3.9, 5.1, 6.6, 7.8]
    for i, v0 in enumerate(rows):
        if i in (2, 4):
            b.box(10.0, v0, 14.0, v0 + 0.6); b.box(14.85, v0, 19.0, v0 + 0.6)     # cross-over gap 0.85 m
        else:
            b.box(10.0, v0, 19.0, v0 + 0.6)
    # aisles: 1.5..2.4 (0.9), 3.0..3.9 (0.9), 4.5..5.1 (0.6), 5.7..6.6 (0.9), 7.2..7.8 (0.6), 8.4..10 (1.6)
    for vv, note in [(1.95, "data hall: cold aisle between rack rows 1 and 2"),
                     (3.45, "data hall: hot aisle between rack rows 2 and 3"),
                     (6.15, "data hall: hot aisle between rack rows 4 and 5")]:
        b.passage(15.5, vv, 0.9, note, across=(0, 1))
    b.passage(15.5, 4.8, 0.6, "data hall: hot aisle between rack rows 3 and 4 (0.6 m)", across=(0, 1))
    b.passage(15.5, 7.5, 0.6, "data hall: hot aisle between rack rows 5 and 6 (0.6 m)", across=(0, 1))
    b.passage(15.5, 0.51, 0.78, "data hall: strip between rack row 1 and the south wall", across=(0, 1))
    b.passage(14.43, 4.2, 0.85, "data hall: cross-over gap in rack row 3", across=(1, 0))
    b.passage(14.43, 6.9, 0.85, "data hall: cross-over gap in rack row 5", across=(1, 0))
    # cooling units on the east wall, PDU cabinets
    for v0 in (0.6, 3.6, 6.6):
        b.box(20.9, v0, 21.88, v0 + 1.8)
    b.box(8.12, 8.8, 9.0, 9.9)
    # UPS room 8..15 x 10..15
    b.box(9.0, 13.6, 13.0, 14.88); b.box(13.6, 10.1, 14.88, 11.3)
    # battery room 15..22: battery racks N-S, 0.8 m aisles
    for u0 in (16.6, 18.1, 19.6):
        b.box(u0, 11.4, u0 + 0.7, 14.6)
    b.passage(17.7, 13.0, 0.8, "battery room: aisle between battery racks 1 and 2", across=(1, 0))
    b.passage(19.2, 13.0, 0.8, "battery room: aisle between battery racks 2 and 3", across=(1, 0))
    b.outside(8, dmin=1.5, dmax=5.0)
    b.person([(9.0, 2.0), (9.0, 8.5), (19.8, 8.8)], speed=0.15)
    b.person([(15.5, 9.6)], start=0, stop=400)
    b.space(3.0, 2.0, "room", "security lobby", region=(0.6, 0.5, 5.6, 3.6))
    b.space(5.0, 8.1, "room", "network operations centre", region=(0.8, 4.3, 5.6, 8.6))
    b.space(3.0, 12.0, "room", "staging room", region=(0.6, 9.4, 5.6, 14.6))
    b.space(7.0, 7.5, "hallway", "service corridor", region=(6.2, 0.5, 7.8, 14.5))
    b.space(9.2, 5.0, "room", "data hall", region=(8.3, 0.3, 21.0, 9.8))
    b.space(11.5, 12.2, "room", "UPS room", region=(8.3, 10.3, 14.7, 14.7))
    b.space(16.0, 12.0, "room", "battery room", region=(15.2, 10.3, 21.7, 14.7))
    T = b.tour
    T([(3.0, 1.3), (2.2, 2.2), (4.4, 3.4), (4.4, 4.8), (1.2, 6.5), (5.0, 8.4), (5.3, 6.5), (7.0, 6.5), (7.0, 2.0),
       (7.0, 12.0), (4.5, 12.5), (1.5, 12.0), (3.8, 14.6), (4.5, 11.5), (7.0, 12.0), (7.0, 5.0), (9.3, 5.0),
       (9.3, 0.51), (20.2, 0.51), (20.2, 9.2), (9.5, 9.2), (9.5, 1.95), (19.6, 1.95), (20.2, 3.45), (9.5, 3.45), (9.5, 6.15),
       (19.8, 6.15), (20.2, 8.9), (9.5, 9.1), (9.3, 5.0), (7.0, 5.0), (7.0, 12.5), (9.0, 12.5),
       (11.5, 12.0), (14.0, 12.5), (15.8, 12.5), (15.8, 10.8), (21.2, 10.8), (21.2, 14.6), (19.2, 14.6), (19.2, 11.0),
       (17.7, 11.0), (17.7, 14.6), (15.8, 12.5), (9.0, 12.5), (7.0, 12.5), (7.0, 14.5)])
    T([(7.0, 14.5), (7.0, 5.0), (9.5, 5.0), (9.5, 6.15), (20.2, 6.15), (20.2, 9.0), (9.5, 9.0), (9.3, 5.0), (7.0, 5.0), (7.0, 0.6)],
      bias=(0.05, 0.06, -0.45))
    return b


# ----------------------------------------------------------------------------------------------
def lecture_wing():
    b = B("b8_lecture_wing", "University lecture wing (34 x 22 m, rotated 41 deg, 0.05 m cells, front-facing 270 deg "
          "lidar): a foyer (1.8 m glass entrance double door in a glass facade, a boxed-in open stair, cafe counter "
          "and tables) with a 1.8 m double door onto a 2.4 m corridor the length of the wing (one hallway); south: "
          "lecture hall A (two 1.6 m double doors, a 1.0 m fire exit; fixed bench rows in two blocks with a 0.9 m "
          "centre aisle = passage) and a seminar-style lecture room B (1.2 m); north: three seminar rooms (0.9 m; "
          "two seen only through their doors), a computer lab (two 1.0 m doors; PC desk rows), and a study room "
          "(1.2 m). Students walking. Hard: glass facade, bench rows, partly explored rooms, blind sector.",
          (34, 22), theta=41, seed=44, margin=8.0, res=0.05, fov=270)
    w = b.wall
    w((0, 0), (10, 0), glass=True, doors=[(5.0, 1.8, "foyer glass entrance double door (to outside)", ("d", -1, 90))])
    w((10, 0), (34, 0), EXT, doors=[(6.0, 1.0, "lecture hall A front fire exit (to outside)", ("a", 1, 90))])
    w((34, 0), (34, 22), EXT, doors=[(11.2, 1.2, "corridor east fire exit (to outside)", ("a", -1, 80))])
    w((34, 22), (0, 22), EXT, windows=[(1.0, 4.0), (7.0, 10.0), (13.0, 16.0), (19.0, 22.0), (25.0, 28.0), (29.0, 33.0)])
    w((0, 22), (0, 0), EXT)
    w((0, 10), (10, 10), doors=[(5.0, 1.8, "foyer to corridor (double door)", ("d", 1, 90))])
    w((10, 10), (34, 10), doors=[(2.0, 1.6, "corridor to lecture hall A (rear west double door)", ("d", -1, 90)),
                                 (11.5, 1.6, "corridor to lecture hall A (rear east double door)", ("d", -1, 90)),
                                 (19.0, 1.2, "corridor to lecture room B", ("a", -1, 90))])
    w((10, 0), (10, 10), 0.24); w((24, 0), (24, 10), 0.24)
    w((0, 12.4), (34, 12.4), doors=[(3.0, 0.9, "corridor to seminar room 1", ("a", 1, 90)),
                                    (9.0, 0.9, "corridor to seminar room 2", ("b", 1, 85)),
                                    (15.0, 0.9, "corridor to seminar room 3", ("a", 1, 90)),
                                    (19.2, 1.0, "corridor to computer lab (west door)", ("a", 1, 90)),
                                    (24.8, 1.0, "corridor to computer lab (east door)", ("b", 1, 90)),
                                    (30.0, 1.2, "corridor to study room", ("a", 1, 90))])
    for u in (6, 12, 18, 26):
        w((u, 12.4), (u, 22))
    # foyer: stair box, cafe counter, tables
    b.box(0.12, 4.0, 2.6, 9.2)
    b.box(7.0, 6.8, 9.88, 7.5); b.box(9.2, 7.5, 9.88, 9.88)
    for (u, v) in [(4.2, 3.0), (7.0, 3.0), (4.2, 5.6)]:
        b.table(u - 0.4, v - 0.4, u + 0.4, v + 0.4); b.chair(u - 0.7, v, 0); b.chair(u + 0.7, v, 0)
    # lecture hall A 10..24 x 0..10: lectern zone v 0..2.5, bench rows v 2.8..9 (0.35 deep, pitch 0.95)
    b.box(17.5, 1.0, 20.0, 1.6)                                      # lectern
    v = 2.8
    while v < 8.0:
        b.box(11.3, v, 16.55, v + 0.4); b.box(17.45, v, 22.7, v + 0.4)
        v += 0.95
    b.passage(17.0, 5.6, 0.9, "lecture hall A: centre aisle between the bench blocks", across=(1, 0))
    # lecture room B 24..34: movable tables in U
    b.table(26.0, 2.0, 32.0, 2.8); b.table(26.0, 2.8, 26.8, 7.0); b.table(31.2, 2.8, 32.0, 7.0)
    for u in (27.0, 28.5, 30.0): b.chair(u, 3.2)
    b.box(33.3, 0.5, 33.88, 2.5)
    # seminar rooms: tables
    for u0 in (0, 6, 12):
        b.table(u0 + 1.5, 15.5, u0 + 4.5, 17.5)
        for du in (2.0, 3.0, 4.0): b.chair(u0 + du, 15.1)
        b.box(u0 + 0.2, 21.2, u0 + 2.0, 21.88)
    # computer lab 18..26: desk rows with PCs (panels)
    for vv in (14.2, 16.6, 19.0):
        b.desk(19.2, vv, 24.8, vv + 0.8, "n")
        for u in (19.8, 20.9, 22.0, 23.1, 24.2): b.chair(u, vv - 0.4)
    # study room 26..34: carrels along the walls, big table
    b.table(28.0, 16.0, 32.0, 18.0)
    b.clutter((26.12, 21.88), (34, 21.88), -1, 3)
    b.box(33.3, 13.0, 33.88, 15.5)
    # corridor clutter: benches, lockers
    b.box(12.0, 12.0, 14.0, 12.28); b.box(26.5, 10.12, 28.5, 10.5)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(3.0, 11.2), (30.0, 11.2)], speed=0.3)
    b.person([(22.0, 1.0)], start=0, stop=1200)
    b.person([(5.0, 1.5), (5.0, 8.0)], speed=0.2, start=100, stop=700)
    b.person([(28.5, 15.0)], start=0)
    b.space(5.0, 2.0, "room", "foyer", region=(2.8, 0.4, 9.6, 9.6))
    b.space(20.0, 11.2, "hallway", "corridor", region=(0.5, 10.3, 33.5, 12.1))
    b.space(13.0, 1.8, "room", "lecture hall A", region=(10.4, 0.3, 23.6, 2.6))
    b.space(29.0, 5.0, "room", "lecture room B", region=(24.4, 0.3, 33.6, 9.7))
    b.space(3.0, 19.2, "room", "seminar room 1", region=(0.4, 12.8, 5.7, 21.6))
    b.space(9.0, 19.2, "room", "seminar room 2", region=(6.3, 12.8, 11.7, 21.6))
    b.space(15.0, 19.2, "room", "seminar room 3", region=(12.3, 12.8, 17.7, 21.6))
    b.space(22.0, 20.5, "room", "computer lab", region=(18.3, 12.8, 25.7, 21.6))
    b.space(30.0, 20.0, "room", "study room", region=(26.3, 12.8, 33.6, 21.6))
    T = b.tour
    T([(5.0, -0.8), (5.0, 1.5), (8.5, 1.5), (8.5, 5.5), (3.3, 5.8), (3.3, 2.0), (5.0, 7.8), (5.0, 11.2), (12.0, 11.2),
       (12.0, 8.9), (10.7, 5.0), (10.7, 2.2), (16.0, 2.0), (23.3, 2.2), (23.3, 9.0), (17.0, 9.0), (17.0, 2.3),
       (21.5, 9.0), (21.5, 11.2), (29.0, 11.2), (29.0, 9.3), (25.0, 8.5), (25.0, 1.0), (33.0, 1.0),
       (33.0, 3.5), (29.0, 9.0), (29.0, 11.2), (30.0, 11.2), (30.0, 14.0), (33.0, 19.5), (27.0, 19.5), (27.0, 14.0),
       (30.0, 14.0), (30.0, 11.2), (24.8, 11.2), (24.8, 13.6), (25.4, 15.5), (18.7, 15.5), (18.7, 18.0), (25.4, 18.0),
       (25.4, 20.6), (18.7, 20.6), (18.7, 13.8), (19.2, 11.2), (15.0, 11.2), (15.0, 14.0), (13.0, 14.0), (12.8, 20.5),
       (16.8, 20.5), (17.2, 14.0), (15.0, 13.8), (15.0, 11.2), (0.8, 11.2)])
    T([(0.8, 11.2), (33.0, 11.2)], bias=(-0.08, 0.05, 0.5))
    return b


# ----------------------------------------------------------------------------------------------
def post_office():
    b = B("b8_post_office", "Post office with a mail sorting hall (30 x 20 m, rotated -62 deg, 0.05 m cells): public "
          "hall (1.6 m entrance double door, P.O. box wall, card / packaging gondolas with 0.9 m aisles = passages, "
          "queue posts) behind a solid counter wall with three glass counter windows and a 0.9 m security door; "
          "counter back office; a 1.8 m staff corridor (one hallway) with the manager's office, staff room, toilets "
          "and a 1.2 m door into the sorting hall; a 18 x 20 m sorting hall (sorting frames, a conveyor on legs, roll "
          "cages, parcel shelving with 0.9 m aisles = passages, delivery frames along the walls, a 1.8 m yard double "
          "door and a 1.0 m side door). Staff walking. Hard: counter windows, big cluttered hall, shelving aisles.",
          (30, 20), theta=-62, seed=45, margin=8.0, res=0.05)
    w = b.wall
    w((0, 0), (12, 0), EXT, doors=[(5.0, 1.6, "entrance double door (public hall to outside)", ("d", 1, 85))],
      windows=[(1.0, 3.6), (7.0, 11.0)])
    w((12, 0), (30, 0), EXT, doors=[(14.0, 1.8, "sorting hall yard double door (to outside)", ("d", -1, 90))])
    w((30, 0), (30, 20), EXT, doors=[(16.5, 1.0, "sorting hall side door (to outside)", ("a", -1, 90))])
    w((30, 20), (0, 20), EXT, windows=[(20.0, 24.0)])
    w((0, 20), (0, 0), EXT)
    w((0, 7), (12, 7), 0.3, doors=[(11.0, 0.9, "public hall to back office (security door)", ("b", 1, 90))],
      windows=[(2.6, 4.2), (5.0, 6.6), (7.4, 9.0)])
    w((12, 0), (12, 20), doors=[(9.0, 1.0, "back office to sorting hall", ("a", -1, 90)),
                                (12.0, 1.2, "staff corridor to sorting hall", ("b", -1, 90))])
    w((0, 11), (12, 11), doors=[(2.0, 0.9, "back office to staff corridor", ("a", 1, 90))])
    w((0, 12.8), (12, 12.8), doors=[(2.0, 0.9, "staff corridor to manager's office", ("b", 1, 90)),
                                    (6.0, 0.9, "staff corridor to staff room", ("a", 1, 90)),
                                    (10.0, 0.8, "staff corridor to toilets", ("a", 1, 90))])
    w((4, 12.8), (4, 20)); w((8.5, 12.8), (8.5, 20))
    # public hall: PO boxes west wall, gondolas, queue posts
    b.box(0.12, 0.6, 0.6, 6.4)
    for u0 in (1.5, 2.9):
        b.box(u0, 1.4, u0 + 0.5, 4.2)
    b.passage(2.45, 2.8, 0.9, "public hall: aisle between the two card / packaging gondolas", across=(1, 0))
    b.passage(1.05, 2.8, 0.9, "public hall: aisle between the P.O. boxes and the first gondola", across=(1, 0))
    for u in (5.0, 6.2, 7.4, 8.6):
        b.dot(u, 5.4, 0.03); b.dot(u, 4.2, 0.03)
    b.box(10.5, 0.4, 11.88, 1.0)
    # back office: counter desks along the counter wall, safe
    for u0 in (2.6, 5.0, 7.4):
        b.desk(u0, 7.2, u0 + 1.6, 7.9, None); b.chair(u0 + 0.8, 8.4)
    b.box(0.12, 9.6, 1.2, 10.88); b.box(9.0, 10.2, 11.0, 10.88)
    # rooms north of the staff corridor
    b.desk(0.3, 18.6, 2.0, 19.5, "n"); b.chair(1.2, 18.1); b.box(3.3, 14.0, 3.88, 16.0)
    b.table(5.2, 15.5, 7.2, 16.7); b.box(4.12, 19.2, 8.38, 19.88)
    for (u, v) in [(5.6, 15.1), (6.8, 15.1), (5.6, 17.1)]: b.chair(u, v)
    b.seg((9.6, 19.88), (9.6, 18.4), 0.05); b.seg((10.8, 19.88), (10.8, 18.4), 0.05); b.box(11.3, 13.0, 11.88, 15.0)
    # sorting hall 12..30 x 0..20
    for (u0, v0) in [(14.0, 3.0), (14.0, 6.5), (19.0, 3.0), (19.0, 6.5)]:       # sorting frames (back to back)
        b.box(u0, v0, u0 + 3.5, v0 + 0.9)
    for k in range(12):                                                          # conveyor legs
        u = 14.0 + k * 0.8
        b.dot(u, 10.0, 0.035); b.dot(u, 10.7, 0.035)
    for (u, v, a) in [(24.5, 2.5, 10), (25.4, 2.6, -5), (25.0, 4.0, 30), (13.0, 15.5, 0), (13.0, 16.5, 5), (16.5, 12.5, 45)]:
        b.rbox(u, v, 0.7, 0.8, a)                                                # roll cages
    # parcel shelving NE: rows E-W at u 19..27, depth 0.5, aisles 0.9
    for v0 in (13.0, 14.4, 15.8, 17.2):
        b.box(19.0, v0, 27.0, v0 + 0.5)
    b.passage(23.0, 13.95, 0.9, "sorting hall: parcel shelving aisle 1", across=(0, 1))
    b.passage(23.0, 15.35, 0.9, "sorting hall: parcel shelving aisle 2", across=(0, 1))
    b.passage(23.0, 16.75, 0.9, "sorting hall: parcel shelving aisle 3", across=(0, 1))
    b.clutter((12.12, 19.88), (30, 19.88), -1, 5, avoid=[(0, 7.5)])
    b.clutter((29.88, 0), (29.88, 20), 1, 4, avoid=[(15.5, 17.5)])
    b.box(27.8, 6.0, 29.88, 9.0)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(13.2, 2.0), (13.2, 9.2), (24.0, 9.2)], speed=0.15)
    b.person([(4.4, 9.6)], start=0, stop=1000)
    b.person([(4.0, 5.8)], start=300)
    b.space(7.0, 2.6, "room", "public hall", region=(3.6, 0.4, 11.6, 6.6))
    b.space(6.0, 9.6, "room", "counter back office", region=(1.4, 8.7, 11.6, 10.7))
    b.space(6.0, 11.9, "hallway", "staff corridor", region=(0.5, 11.2, 11.5, 12.6))
    b.space(2.0, 16.0, "room", "manager's office", region=(0.3, 13.0, 3.7, 19.7))
    b.space(6.2, 18.0, "room", "staff room", region=(4.3, 13.0, 8.2, 19.7))
    b.space(10.2, 16.5, "room", "toilets", region=(8.7, 13.2, 11.8, 18.2))
    b.space(21.0, 9.0, "room", "sorting hall", region=(12.3, 0.3, 29.7, 19.7))
    T = b.tour
    T([(5.0, -0.8), (5.0, 1.0), (9.5, 3.2), (9.5, 6.2), (4.0, 6.3), (2.45, 4.9), (2.45, 0.8), (1.05, 0.5), (1.05, 4.9),
       (4.0, 6.3), (10.0, 6.3), (11.0, 6.3), (11.0, 8.4), (9.0, 9.6), (2.0, 9.6), (2.0, 11.9), (8.0, 11.9), (10.0, 11.9),
       (10.0, 13.8), (10.2, 16.8), (10.0, 13.8), (10.0, 11.9), (6.0, 11.9), (6.0, 14.4), (7.8, 18.3), (4.6, 18.0),
       (6.0, 14.4), (6.0, 11.9), (2.0, 11.9), (2.0, 14.5), (2.2, 17.5), (2.0, 14.5), (2.0, 11.9), (12.9, 11.9),
       (12.9, 9.0), (13.2, 2.0), (18.2, 2.0), (18.2, 5.0), (23.0, 5.0), (23.0, 2.0), (28.5, 1.5), (28.5, 11.5),
       (18.0, 11.5), (13.2, 11.8), (13.2, 18.6), (18.0, 18.6), (18.0, 12.3), (28.0, 12.3), (28.0, 18.4), (18.3, 18.4),
       (18.3, 16.75), (27.6, 16.75), (27.6, 15.35), (18.3, 15.35), (18.3, 13.95), (28.0, 13.95), (29.0, 16.5)])
    T([(29.0, 16.5), (28.4, 11.6), (22.0, 11.6), (22.0, 8.4), (13.2, 8.4), (12.9, 11.9), (6.0, 11.9), (2.0, 11.9), (2.0, 9.6),
       (9.0, 9.6), (11.0, 8.4), (11.0, 6.3), (5.0, 1.0)], bias=(0.06, 0.07, 0.55))
    return b


# ----------------------------------------------------------------------------------------------
def hostel():
    b = B("b8_hostel", "Backpackers' hostel ground floor (30 x 14 m, rotated 96 deg, 0.05 m cells, front-facing 270 "
          "deg lidar): an open common room (1.2 m entrance door, reception desk, lounge with sofas) and a communal "
          "kitchen behind a stub wall (3 m opening: kitchen and lounge GROUPED; a kitchen island leaves a 0.85 m "
          "squeeze = passage) and a back door; a 1.2 m fire door onto a 1.8 m corridor (one hallway); south: dorms 1 "
          "and 2 (1.0 m doors; bunk beds and lockers, 0.8 m gaps = passages), shared shower room (1.0 m), dorm 3 at "
          "the far end (not entered); north: two private rooms (0.9 m), laundry (0.9 m), a closed luggage store, dorm "
          "4 (not entered). The robot turned back part-way along the corridor: the east end is partly explored. "
          "Guests walking. Hard: partly explored wing, bunk beds, blind sector.",
          (30, 14), theta=96, seed=46, margin=8.0, res=0.05, fov=270)
    w = b.wall
    w((0, 0), (30, 0), EXT, doors=[(4.0, 1.2, "entrance door (common room to outside)", ("a", 1, 90))],
      windows=[(7.0, 11.0), (13.5, 15.5), (18.5, 20.5), (26.0, 28.0)])
    w((30, 0), (30, 14), EXT, doors=[(6.9, 1.0, "corridor east fire exit (to outside)", ("a", -1, 90))])
    w((30, 14), (0, 14), EXT, doors=[(19.5, 1.0, "kitchen back door (to the yard)", ("b", -1, 85))],
      windows=[(1.5, 3.5), (8.0, 10.0), (12.0, 14.0), (20.0, 22.0)])
    w((0, 14), (0, 0), EXT)
    # common room u 0..12; stub wall between lounge (south) and kitchen (north) at v 8, u 0..9 (opening 9..12)
    w((0, 8.2), (9.0, 8.2))
    w((12, 0), (12, 14), doors=[(6.9, 1.2, "common room to corridor (fire door)", ("a", -1, 90))])
    # corridor v 6..7.8, u 12..30
    w((12, 6), (30, 6), doors=[(2.5, 1.0, "corridor to dorm 1", ("a", -1, 90)),
                               (7.5, 1.0, "corridor to dorm 2", ("a", -1, 90)),
                               (11.5, 1.0, "corridor to shower room", ("b", -1, 90)),
                               (15.5, 1.0, "corridor to dorm 3", ("a", -1, 85))])
    w((12, 7.8), (30, 7.8), doors=[(1.75, 0.9, "corridor to private room 1", ("a", 1, 90)),
                                   (5.25, 0.9, "corridor to private room 2", ("a", 1, 90)),
                                   (8.5, 0.9, "corridor to laundry", ("b", 1, 90)),
                                   {"at": 11.0, "w": 0.9, "note": "luggage store (closed)", "closed": True},
                                   (15.0, 1.0, "corridor to dorm 4", ("b", 1, 90))])
    for u in (17, 22, 25):
        w((u, 0), (u, 6))
    for u in (15.5, 19, 22, 24):
        w((u, 7.8), (u, 14))
    # lounge: sofas, reception desk, coffee table
    b.box(0.5, 0.3, 2.5, 1.2); b.box(0.12, 2.0, 0.9, 5.0); b.table(2.0, 2.5, 3.2, 3.5); b.box(3.8, 2.8, 4.6, 4.6)
    b.box(9.0, 0.8, 9.6, 3.5); b.box(9.6, 2.9, 11.5, 3.5)                            # L reception desk
    b.box(6.0, 7.5, 8.8, 8.1)                                                       # bookshelf on the stub wall
    # kitchen u 0..12 x 8.2..14: counter along the north wall, island -> 0.85 m
    b.box(0.12, 13.2, 7.0, 13.88); b.box(0.12, 8.3, 0.75, 13.2)
    b.box(1.6, 11.45, 5.5, 12.35)
    b.passage(3.5, 12.775, 0.85, "kitchen: squeeze between the island and the counter", across=(0, 1))
    for (u0, v0) in [(7.5, 10.0), (7.5, 12.0)]:
        b.table(u0, v0, u0 + 2.6, v0 + 0.9)
        for du in (0.5, 1.3, 2.1): b.chair(u0 + du, v0 - 0.35)
    b.box(11.2, 12.0, 11.88, 13.88)
    # dorms: bunks (0.9 x 2.0) along the side walls, lockers at the window
    for u0 in (12, 17, 25):
        for k in range(2):
            b.box(u0 + 0.15, 0.5 + 2.05 * k, u0 + 1.05, 2.45 + 2.05 * k)                  # west bunks
            b.box(u0 + 3.95, 0.5 + 2.05 * k, u0 + 4.85, 2.45 + 2.05 * k)                  # east bunks
        b.box(u0 + 1.85, 1.0, u0 + 3.15, 3.8)                                         # central locker / wardrobe block
    for u0, nm in ((12, "dorm 1"), (17, "dorm 2"), (25, "dorm 3")):
        b.passage(u0 + 1.45, 2.4, 0.8, f"{nm}: gap between the west bunks and the locker block", across=(1, 0))
        b.passage(u0 + 3.55, 2.4, 0.8, f"{nm}: gap between the locker block and the east bunks", across=(1, 0))
    # shower room 22..25: cubicle partitions
    for u in (22.9, 23.9):
        b.seg((u, 0.12), (u, 1.5), 0.05)
    b.box(24.4, 3.6, 24.88, 5.4)
    # private rooms, laundry, dorm 4
    b.box(12.2, 12.0, 14.0, 13.88); b.box(15.7, 12.0, 17.5, 13.88); b.box(14.6, 8.0, 15.38, 9.0)
    b.box(19.2, 12.8, 21.88, 13.88); b.box(21.2, 9.5, 21.88, 11.5)
    for k in range(2):
        b.box(24.2, 12.0 - 2.1 * k, 26.2, 12.9 - 2.1 * k); b.box(27.8, 12.0 - 2.1 * k, 29.8, 12.9 - 2.1 * k)
    b.outside(10, dmin=1.5, dmax=6.0)
    b.person([(2.0, 6.0), (6.0, 6.5)], speed=0.1)
    b.person([(13.0, 6.9), (26.0, 6.9)], speed=0.25, start=200)
    b.person([(9.0, 11.3)], start=0, stop=900)
    b.space(6.5, 4.5, "room", "common room lounge", group="common room", region=(1.0, 1.3, 8.8, 7.6))
    b.space(4.0, 10.0, "room", "communal kitchen", group="common room", region=(1.0, 8.5, 7.2, 11.2))
    b.space(21.0, 6.9, "hallway", "corridor", region=(12.5, 6.2, 29.5, 7.6))
    b.space(14.5, 4.6, "room", "dorm 1", region=(13.3, 0.8, 15.8, 5.8))
    b.space(19.5, 4.6, "room", "dorm 2", region=(18.3, 0.8, 20.8, 5.8))
    b.space(23.5, 3.0, "room", "shower room", region=(22.2, 1.6, 24.3, 5.8))
    b.space(27.5, 4.6, "room", "dorm 3", region=(26.3, 0.8, 28.8, 5.8))
    b.space(13.75, 10.0, "room", "private room 1", region=(12.2, 8.0, 15.3, 11.8))
    b.space(17.25, 10.0, "room", "private room 2", region=(15.7, 8.0, 18.8, 11.8))
    b.space(20.5, 10.5, "room", "laundry", region=(19.2, 8.0, 21.0, 12.6))
    b.space(27.0, 10.0, "room", "dorm 4", region=(24.3, 8.0, 29.7, 13.7))
    T = b.tour
    dorm = lambda u0: [(u0 + 2.5, 6.9), (u0 + 2.9, 5.0), (u0 + 1.45, 4.0), (u0 + 1.45, 0.6), (u0 + 3.55, 0.6),
                       (u0 + 3.55, 4.0), (u0 + 2.9, 5.0), (u0 + 2.5, 6.9)]
    T([(4.0, -0.8), (4.0, 1.8), (6.0, 1.5), (7.5, 5.5), (2.0, 6.5), (1.5, 7.2), (10.5, 7.0), (10.5, 10.0), (10.6, 13.3),
       (6.0, 12.8), (1.3, 12.8), (1.3, 11.0), (6.0, 11.0), (6.8, 9.0), (10.5, 7.0), (13.0, 6.9)] + dorm(12) +
      [(17.25, 6.9), (17.25, 11.3), (17.25, 6.9)] + dorm(17) +
      [(20.5, 6.9), (20.5, 11.5), (20.5, 6.9), (23.5, 6.9), (19.0, 6.9), (12.8, 6.9), (11.0, 6.9), (6.0, 5.0),
       (4.0, 1.8), (4.0, 0.4)])
    T([(4.0, 0.4), (4.0, 2.0), (10.5, 6.8), (22.0, 6.9), (21.0, 6.9), (13.75, 6.9), (13.75, 9.5), (13.75, 6.9), (10.5, 6.8),
       (4.0, 2.0)], bias=(0.05, -0.07, -0.5))
    return b


BUILDINGS = [nursing_home, police_station, data_centre, lecture_wing, post_office, hostel]
