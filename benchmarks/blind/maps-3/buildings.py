"""The blind3 buildings (building frame: u east, v north, metres). See README.md."""
from sim import B

EXT = 0.22


def home():
    b = B("b3_family_home", "Family home (12 x 9 m, rotated 17 deg): open living room + kitchen with an island "
          "(grouped), an L-shaped entry/hallway with a console table squeezing it to ~0.9 m, three bedrooms, a "
          "bathroom and a utility room seen only through their doors, a closed closet, patio door and front door "
          "open (ray fans). Hard: open living/kitchen, island aisle, rooms seen only through doors.",
          (12, 9), theta=17, seed=1)
    w = b.wall
    w((0, 0), (12, 0), EXT, doors=[(0.9, 0.95, "front door to outside", ("a", -1, 100))],
      )
    w((12, 0), (12, 9), EXT)
    w((12, 9), (0, 9), EXT)
    w((0, 9), (0, 0), EXT, doors=[(2.6, 1.0, "patio door (living room to garden)", ("b", 1, 90))],
      windows=[(3.3, 4.6)])
    w((0, 4.5), (12, 4.5), doors=[(1.0, 0.9, "hallway to living room"),
                                 (8.5, 0.8, "hallway to bathroom", ("a", 1, 95)),
                                 (10.6, 0.85, "hallway to bedroom 3", ("b", 1, 100))])
    w((1.8, 3.2), (12, 3.2), doors=[(1.3, 0.85, "hallway to bedroom 1", ("a", -1, 95)),
                                   (6.2, 0.85, "hallway to bedroom 2", ("a", -1, 80)),
                                   (8.9, 0.8, "hallway to utility room", ("b", -1, 110))])
    w((1.8, 0), (1.8, 3.2))
    w((6.0, 0), (6.0, 3.2))
    w((9.5, 0), (9.5, 3.2))
    w((7.5, 4.5), (7.5, 9))
    w((9.5, 4.5), (9.5, 9))
    w((7.5, 7.4), (9.5, 7.4), doors=[{"at": 1.0, "w": 0.7, "note": "closet", "closed": True}])
    # living
    b.box(0.5, 6.4, 2.7, 7.3)           # sofa
    b.table(1.0, 5.4, 2.2, 5.9)         # coffee table
    b.box(3.6, 8.3, 4.4, 8.8)           # tv unit
    b.box(4.6, 8.35, 7.4, 8.85)         # kitchen counter
    b.box(5.2, 6.6, 6.8, 7.45)          # island
    b.table(2.8, 5.2, 4.0, 6.2)         # dining table
    for p in [(2.6, 5.5), (2.6, 5.95), (4.2, 5.5), (4.2, 5.95)]:
        b.chair(*p)
    b.box(7.0, 4.65, 7.4, 6.2)          # fridge/tall cabinet
    b.passage(6.0, 7.9, 0.9, "kitchen aisle between island and counter", across=(0, 1))
    # hallway
    b.box(0.1, 0.5, 0.45, 1.8)          # shoe cabinet
    b.box(4.9, 4.02, 6.1, 4.38)         # console table against north hallway wall
    b.passage(5.5, 3.66, 0.76, "hallway squeeze beside the console table", across=(0, 1))
    # bedrooms
    b.box(4.0, 0.2, 5.85, 1.8)          # bed 1
    b.box(1.95, 0.2, 2.5, 1.9)          # wardrobe
    b.box(6.6, 0.15, 8.2, 2.1)          # bed 2
    b.box(9.9, 6.8, 11.85, 8.85)        # bed 3
    b.box(9.65, 4.65, 10.1, 5.9)        # desk/dresser
    b.box(10.0, 0.15, 11.85, 0.8)       # washer/dryer
    b.box(7.65, 4.65, 8.1, 6.0)         # bath tub side
    b.outside(14)
    b.space(2.0, 7.8, "room", "living room", group="living", region=(0.2, 4.7, 4.4, 8.8))
    b.space(6.0, 5.7, "room", "kitchen", group="living", region=(4.5, 4.7, 7.3, 8.3))
    b.space(0.9, 2.0, "hallway", "entry + hallway", region=(0.1, 0.2, 1.7, 4.4))
    b.space(3.3, 2.6, "room", "bedroom 1", region=(1.9, 0.1, 5.9, 3.1))
    b.space(7.8, 2.6, "room", "bedroom 2", region=(6.1, 0.1, 9.4, 3.1))
    b.space(10.7, 2.0, "room", "utility room", region=(9.6, 0.1, 11.9, 3.1))
    b.space(8.8, 6.0, "room", "bathroom", region=(7.6, 4.6, 9.4, 7.3))
    b.space(10.7, 5.8, "room", "bedroom 3", region=(9.6, 4.6, 11.9, 8.9))
    b.route([(0.9, 0.6), (0.9, 3.75), (1.0, 5.2), (3.0, 4.85), (4.7, 5.0), (4.7, 7.9), (3.2, 7.9), (0.45, 7.9),
             (3.2, 7.9), (5.0, 8.0), (6.9, 7.95), (5.0, 8.0), (4.7, 6.0), (6.0, 6.1), (4.5, 5.0), (1.0, 4.9),
             (1.0, 3.75), (5.5, 3.7), (10.6, 3.7), (10.6, 6.0), (10.6, 3.7),
             (3.3, 3.7), (3.3, 2.6), (5.0, 2.5), (3.3, 2.6), (3.2, 1.0), (3.3, 2.6), (3.3, 3.75), (1.0, 3.75), (0.9, 1.0)])
    return b




def office():
    b = B("b3_office_glass", "Open-plan office (24 x 16 m, rotated -31 deg): reception with a 1.6 m entrance door, "
          "one big open-plan floor with desk clusters (legs + modesty panels + chairs), a row of three glass-fronted "
          "meeting rooms and a glass-fronted manager office (glass seen only near normal incidence: dashed fronts, "
          "rays through the glass map the rooms behind), kitchen, print room, closed server room. Two squeezes "
          "(cabinets vs desk cluster, planter vs column). Hard: glass fronts whose doors sit in dashed lines; "
          "open plan must stay ONE room.", (24, 16), theta=-31, seed=2)
    w = b.wall
    w((0, 0), (24, 0), EXT, doors=[(2.5, 1.6, "main entrance (double door) to outside", ("a", -1, 95))])
    w((24, 0), (24, 16), EXT, doors=[(6.0, 0.9, "fire exit to outside", ("b", 1, 100))])
    w((24, 16), (0, 16), EXT)
    w((0, 16), (0, 0), EXT)
    w((0, 4), (5, 4), doors=[(2.5, 1.8, "reception to open-plan floor")])
    w((5, 0), (5, 4))
    w((5, 3), (11, 3), doors=[{"at": 1.5, "w": 0.9, "note": "server room", "closed": True},
                             (4.5, 0.9, "open plan to print room", ("a", 1, 100))])
    w((8, 0), (8, 3))
    w((11, 0), (11, 3))
    # glass meeting rooms on the north side
    w((0, 11.5), (12, 11.5), glass=True, doors=[(2.0, 0.9, "open plan to meeting room 1", ("a", 1, 90)),
                                                (6.0, 0.9, "open plan to meeting room 2", ("b", 1, 100)),
                                                (10.0, 0.9, "open plan to meeting room 3", ("a", 1, 85))])
    w((4, 11.5), (4, 16))
    w((8, 11.5), (8, 16))
    w((12, 11.5), (12, 16))
    w((12, 11.5), (16.5, 11.5), doors=[(2.0, 1.0, "open plan to kitchen")])
    w((16.5, 11.5), (16.5, 16))
    w((16.5, 11.5), (19, 11.5), doors=[{"at": 1.2, "w": 0.8, "note": "toilets", "closed": True}])
    w((19, 11.5), (19, 16))
    w((19, 11.5), (24, 11.5), glass=True, doors=[(1.2, 0.9, "open plan to manager office", ("a", 1, 95))])
    # furniture: meeting tables
    for u0 in (0.8, 4.8, 8.8):
        b.table(u0, 13.0, u0 + 2.4, 14.4, 0.06)
        for k in range(3):
            b.chair(u0 + 0.4 + k * 0.8, 12.6); b.chair(u0 + 0.4 + k * 0.8, 14.8)
    b.desk(20.0, 14.6, 21.6, 15.4, "n"); b.chair(20.8, 14.1)
    b.box(22.8, 12.0, 23.7, 15.8)   # cabinet
    b.box(12.2, 15.3, 16.3, 15.8); b.table(13.5, 13.2, 15.0, 14.2); b.chair(13.2, 13.7); b.chair(15.3, 13.7)
    b.box(8.2, 0.2, 10.8, 0.8)      # printer/copier
    b.box(0.3, 0.5, 2.0, 1.3)       # reception desk
    b.box(3.4, 0.3, 4.7, 0.8)       # bench
    # desk clusters (2 x 3 desks back to back)
    for (u0, v0) in [(2.0, 6.0), (7.5, 6.0), (13.0, 7.3), (17.8, 7.3)]:
        for k in range(3):
            b.desk(u0 + k * 1.4, v0, u0 + k * 1.4 + 1.35, v0 + 0.75, "s")
            b.desk(u0 + k * 1.4, v0 + 0.8, u0 + k * 1.4 + 1.35, v0 + 1.55, "n")
            b.chair(u0 + k * 1.4 + 0.65, v0 + 2.0)
            if u0 != 13.0:
                b.chair(u0 + k * 1.4 + 0.65, v0 - 0.45)
    b.box(13.0, 5.9, 17.2, 6.45)    # storage cabinets south of a cluster
    b.passage(15.2, 6.9, 0.88, "squeeze between storage cabinets and desk cluster", across=(0, 1))
    b.passage(17.47, 8.07, 0.65, "gap between two desk clusters (legs + panel ends)", across=(1, 0), optional=True)
    b.box(21.0, 2.0, 21.6, 2.6)     # column
    b.box(21.6, 0.2, 21.75, 0.3)
    b.box(22.3, 1.8, 23.8, 2.8)     # planter box by the wall
    b.passage(21.95, 2.3, 0.7, "squeeze between column and planter", across=(1, 0))
    b.box(23.0, 7.2, 23.85, 10.8)   # wall of lockers (east)
    b.outside(12)
    b.space(2.4, 2.2, "room", "reception", region=(0.1, 1.4, 4.9, 3.9))
    b.space(11.0, 9.5, "room", "open-plan office floor", region=(0.2, 4.1, 22.5, 11.4))
    b.space(2.0, 15.2, "room", "meeting room 1", region=(0.1, 11.6, 3.9, 15.9))
    b.space(6.0, 15.2, "room", "meeting room 2", region=(4.1, 11.6, 7.9, 15.9))
    b.space(10.0, 15.2, "room", "meeting room 3", region=(8.1, 11.6, 11.9, 15.9))
    b.space(14.2, 12.4, "room", "kitchen", region=(12.1, 11.6, 16.4, 15.2))
    b.space(21.5, 12.7, "room", "manager office", region=(19.1, 11.6, 22.7, 15.9))
    b.space(9.5, 1.8, "room", "print room", region=(8.1, 0.9, 10.9, 2.9))
    b.route([(2.5, 0.8), (2.5, 4.8), (1.2, 5.2), (1.2, 10.5), (6.0, 10.6), (6.0, 12.0), (6.0, 10.6),
             (12.5, 10.5), (14.0, 10.6), (14.0, 12.6), (14.0, 10.6), (17.8, 10.5), (20.2, 10.5), (20.2, 12.6),
             (20.2, 10.5), (22.45, 10.0), (22.45, 3.6), (19.0, 4.5), (17.6, 6.9), (12.6, 6.9), (12.3, 5.2), (11.0, 4.9),
             (9.5, 4.0), (9.5, 2.2), (9.5, 4.2), (6.0, 4.8), (2.5, 4.6), (2.5, 1.0)])
    return b


def ward():
    b = B("b3_care_ward", "Care-home ward (40 x 18 m, axis-aligned): a 2.4 m east-west corridor with a T-junction "
          "(a stem corridor runs north to an exit door) = ONE hallway; resident rooms both sides with 1.1 m doors "
          "(several closed: no point, no door), two rooms with en-suite bathrooms, a day room with a 1.6 m double "
          "door, a linen store; a parked bed + trolley and wheelchairs + a laundry trolley leave two ~0.85 m squeezes in the corridor. Only some rooms "
          "entered; others seen through their doors.", (40, 18), theta=0, seed=3)
    w = b.wall
    w((0, 0), (40, 0), EXT)
    w((40, 0), (40, 18), EXT, doors=[(9.2, 1.2, "corridor east end: fire door to outside", ("a", -1, 80))])
    w((40, 18), (0, 18), EXT, doors=[(20.8, 1.6, "stem corridor: exit double door to garden", ("b", 1, 100))])
    w((0, 18), (0, 0), EXT)
    # south rooms (v 0..8), 4 m wide
    sdoors = []
    closed_s = {3, 7}
    for i in range(10):
        u = i * 4 + 2.0
        if i in closed_s:
            sdoors.append({"at": u, "w": 1.1, "note": f"room S{i+1}", "closed": True})
        else:
            sdoors.append((u, 1.1, f"corridor to room S{i+1}", ("a", -1, 85 + 7 * (i % 4))))
    w((0, 8), (40, 8), doors=sdoors)
    for i in range(1, 10):
        w((i * 4, 0), (i * 4, 8))
    # en-suites in S1 and S5 (SW corner of the room)
    for i in (0, 4):
        u0 = i * 4
        w((u0, 2.4), (u0 + 2.2, 2.4), doors=[(1.5, 0.8, f"room S{i+1} to its en-suite", ("a", 1, 95))])
        w((u0 + 2.2, 0), (u0 + 2.2, 2.4))
    # north side (v 10.4..18)
    ndoors_w = [(2.2, 1.1, "corridor to room N1", ("a", 1, 90)),
                {"at": 6.7, "w": 1.1, "note": "N2", "closed": True},
                (11.2, 1.1, "corridor to room N3", ("a", 1, 100)),
                (15.7, 0.9, "corridor to linen store", ("b", 1, 95))]
    w((0, 10.4), (18, 10.4), doors=ndoors_w)
    w((20.4, 10.4), (40, 10.4), doors=[(2.2, 1.1, "corridor to room N5", ("a", 1, 90)),
                                      (6.7, 1.1, "corridor to room N6", ("b", 1, 105)),
                                      (14.6, 1.6, "corridor to day room (double door)", ("b", 1, 92))])
    for u in (4.5, 9, 13.5):
        w((u, 10.4), (u, 18))
    w((18, 10.4), (18, 18)); w((20.4, 10.4), (20.4, 18))
    w((24.9, 10.4), (24.9, 18)); w((29.4, 10.4), (29.4, 18))
    # furniture: beds etc. in rooms
    for i in range(10):
        u0 = i * 4
        b.box(u0 + 1.5, 4.2, u0 + 2.5, 6.3) if i not in (0, 4) else b.box(u0 + 2.6, 3.0, u0 + 3.6, 5.1)
        b.box(u0 + 0.15, 6.8, u0 + 0.7, 7.8)   # wardrobe
        b.chair(u0 + 3.3, 6.4)
    for u0 in (0, 9, 20.4, 24.9):
        b.box(u0 + 2.0, 15.6, u0 + 3.0, 17.8); b.chair(u0 + 0.8, 16.5)
    b.box(13.7, 10.6, 14.2, 17.7); b.box(17.3, 10.6, 17.8, 17.7)     # linen shelves
    b.table(31.0, 13.0, 33.0, 14.2); b.table(35.0, 13.0, 37.0, 14.2)
    for p in [(30.6, 13.6), (33.4, 13.6), (34.6, 13.6), (37.4, 13.6), (32.0, 12.5), (36.0, 14.7)]:
        b.chair(*p)
    b.box(30.0, 16.6, 32.2, 17.7); b.box(37.0, 16.6, 39.7, 17.7)     # sofas
    # corridor clutter: parked bed on the south wall + trolley opposite -> 0.85 m squeeze
    b.box(28.3, 8.12, 30.4, 9.07); b.box(29.0, 9.9, 29.8, 10.28)
    b.passage(29.4, 9.48, 0.82, "corridor squeeze between parked bed and trolley", across=(0, 1))
    b.box(8.0, 10.0, 9.6, 10.3)   # handrail bench
    b.box(12.0, 8.1, 13.0, 8.8); b.box(12.2, 9.65, 13.0, 10.3)   # parked wheelchairs + laundry trolley
    b.passage(12.6, 9.22, 0.85, "corridor squeeze between wheelchairs and laundry trolley", across=(0, 1))
    b.outside(14)
    b.space(12.0, 9.2, "hallway", "main corridor + stem (T)", region=(0.5, 8.1, 39.5, 10.3))
    for i in range(10):
        if i in closed_s:
            continue
        b.space(i * 4 + 2.0, 1.6 if i not in (0, 4) else 6.0, "room", f"room S{i+1}",
                region=(i * 4 + 0.1, 0.1 if i not in (0, 4) else 2.5, i * 4 + 3.9, 7.9))
    for i in (0, 4):
        b.space(i * 4 + 1.1, 1.2, "room", f"en-suite of S{i+1}", region=(i * 4 + 0.1, 0.1, i * 4 + 2.1, 2.3))
    b.space(2.2, 13.0, "room", "room N1", region=(0.1, 10.5, 4.4, 17.9))
    b.space(11.2, 13.0, "room", "room N3", region=(9.1, 10.5, 13.4, 17.9))
    b.space(15.7, 14.0, "room", "linen store", region=(14.2, 10.5, 17.3, 17.9))
    b.space(22.6, 13.0, "room", "room N5", region=(20.5, 10.5, 24.8, 17.9))
    b.space(27.1, 13.0, "room", "room N6", region=(25.0, 10.5, 29.3, 17.9))
    b.space(34.0, 15.5, "room", "day room", region=(29.5, 10.5, 39.9, 17.9))
    b.route([(1.0, 9.2), (17.0, 9.2), (19.2, 9.2), (19.2, 16.5), (19.2, 9.3), (29.4, 9.5), (38.5, 9.2),
             (34.9, 9.4), (34.9, 11.0), (34.0, 12.0), (34.0, 15.3), (31.0, 15.3), (34.0, 15.3), (34.0, 12.0),
             (34.9, 11.0), (34.9, 9.4), (22.0, 9.2), (22.1, 6.6), (21.0, 6.5), (21.0, 3.0), (21.0, 6.5),
             (22.1, 6.6), (22.0, 9.2), (18.0, 9.2), (18.0, 5.5), (17.6, 3.6), (18.0, 5.5), (18.0, 9.2),
             (2.0, 9.2), (2.0, 5.0), (1.5, 3.2), (1.5, 1.2), (1.5, 3.2), (2.0, 5.0), (2.0, 9.2), (11.2, 9.2),
             (11.2, 12.5), (11.2, 9.2), (1.0, 9.2)])
    return b


def warehouse():
    b = B("b3_warehouse", "Small warehouse (30 x 22 m, rotated 4 deg): pallet-rack rows (pallets with gaps between "
          "them, so rays leak across rows) running north-south with aisles of 1.3, 0.65, 0.85, 1.0 (optional) and "
          "0.75 m, a 3 m main aisle north and a 2 m aisle south (ONE room), an office + kitchenette in the NW "
          "corner, floor pallets, a personnel door open to outside, roller doors closed. Hard: aisles are passages "
          "not doors, racks are not rooms.", (30, 22), theta=4, seed=4)
    w = b.wall
    w((0, 0), (30, 0), EXT + 0.05)
    w((30, 0), (30, 22), EXT + 0.05, doors=[(3.0, 1.0, "personnel door to yard", ("a", 1, 100))])
    w((30, 22), (0, 22), EXT + 0.05)
    w((0, 22), (0, 0), EXT + 0.05)
    w((0, 16), (7, 16), doors=[(5.5, 0.9, "warehouse to office", ("a", 1, 95))])
    w((7, 16), (7, 22), doors=[{"at": 3.0, "w": 1.0, "note": "office internal", "closed": True}])
    w((0, 12.5), (3.5, 12.5))
    w((3.5, 12.5), (3.5, 16), doors=[(1.6, 0.85, "warehouse to kitchenette", ("b", 1, 100))])
    b.box(0.2, 20.8, 2.5, 21.8); b.desk(3.0, 20.9, 4.6, 21.7, "n"); b.chair(3.8, 20.4); b.box(6.2, 16.2, 6.8, 18.5)
    b.box(0.15, 12.7, 0.75, 15.8)   # kitchenette counter
    # racks: rows of pallets (1.2 long, 1.0 deep) north-south from v 4 to v 15
    aisles = [1.3, 0.65, 0.85, 1.0, 0.75]
    u = 9.0
    rows = []
    for k in range(6):
        rows.append(u)
        v = 4.0
        while v < 15.0:
            ln = min(1.2, 15.0 - v)
            b.box(u, v, u + 1.05, v + ln)
            v += ln + b.rng.uniform(0.06, 0.18)
        if k < 5:
            u += 1.05 + aisles[k]
    for k, a in enumerate(aisles):
        cu = rows[k] + 1.05 + a / 2
        if a <= 1.0:
            b.passage(cu, 9.5, a - 0.04, f"rack aisle {k+1} ({a} m)", across=(1, 0), optional=(a >= 1.0))
    # single-sided rack along east wall
    v = 4.0
    while v < 18:
        b.box(28.9, v, 29.85, v + 1.2); v += 1.35
    # floor pallets in the open zone
    for (pu, pv) in [(1.5, 2.0), (3.0, 2.0), (1.5, 6.0), (10.0, 19.5), (11.4, 19.5), (22.0, 20.5), (25.0, 1.0)]:
        b.box(pu, pv, pu + 1.2, pv + 1.0)
    b.box(0.2, 8.0, 0.8, 11.0)      # workbench on west wall
    b.outside(10)
    b.space(4.0, 9.0, "room", "warehouse floor", region=(1.0, 1.0, 8.5, 12.0))
    b.space(3.5, 19.0, "room", "office", region=(0.2, 16.1, 6.9, 21.9))
    b.space(1.8, 14.2, "room", "kitchenette", region=(0.8, 12.6, 3.4, 15.9))
    b.route([(28.0, 3.0), (27.0, 2.6), (5.0, 2.8), (5.0, 15.5), (5.5, 15.6), (5.5, 17.5), (3.0, 18.5),
             (5.5, 17.5), (5.5, 15.6), (5.0, 14.2), (2.0, 14.2), (5.0, 14.2), (8.0, 15.5), (8.0, 17.0),
             (24.0, 17.0), (27.5, 16.0), (27.5, 3.0), (21.0, 2.8), (16.0, 2.8)])
    return b


def school():
    b = B("b3_school_wing", "School wing (36 x 26 m L-shaped footprint, rotated 52 deg): an L-shaped 2.8 m corridor "
          "(east-west leg + north leg, ONE hallway) with lockers, classrooms with table grids (legs) and chairs, "
          "staff room, toilets, a closed store, a library with bookshelf rows (0.85 and 0.8 m aisles = narrow "
          "passages), exit doors at both corridor ends. Only two classrooms and the library entered.",
          (36, 26), theta=52, seed=5)
    b.foot = [(0, 2), (32, 2), (32, 10), (36, 10), (36, 26), (21, 26), (21, 20), (0, 20)]
    w = b.wall
    w((0, 2), (32, 2), EXT); w((32, 2), (32, 10), EXT); w((32, 10), (36, 10), EXT)
    w((36, 10), (36, 26), EXT)
    w((36, 26), (21, 26), EXT, doors=[(7.4, 1.6, "north exit double door", ("a", 1, 95))])
    w((21, 26), (21, 20), EXT); w((21, 20), (0, 20), EXT)
    w((0, 20), (0, 2), EXT, doors=[(8.6, 1.2, "west exit door", ("b", -1, 90))])
    w((0, 10), (28, 10), doors=[(5.5, 1.0, "corridor to classroom 1", ("a", -1, 95)),
                               (12.5, 1.0, "corridor to classroom 2", ("a", -1, 90)),
                               (19.5, 1.0, "corridor to classroom 3", ("b", -1, 100)),
                               {"at": 26.5, "w": 1.0, "note": "C4", "closed": True}])
    w((28, 10), (32, 10), doors=[(1.2, 0.9, "corridor to toilets", ("a", -1, 95))])
    for u in (7, 14, 21, 28):
        w((u, 2), (u, 10))
    w((28, 6), (32, 6))
    w((0, 12.8), (27.2, 12.8), doors=[(6.5, 1.0, "corridor to classroom 5", ("a", 1, 90)),
                                     (14.5, 1.0, "corridor to classroom 6", ("a", 1, 100)),
                                     (19.0, 0.9, "corridor to staff room", ("b", 1, 95)),
                                     {"at": 24.0, "w": 0.9, "note": "store", "closed": True}])
    for u in (8, 16, 21):
        w((u, 12.8), (u, 20))
    w((27.2, 12.8), (27.2, 26), doors=[(10.2, 1.0, "corridor to classroom 7", ("a", -1, 100))])
    w((21, 20), (27.2, 20))
    w((30, 10), (30, 26), doors=[(4.0, 1.0, "corridor to classroom 8", ("b", -1, 95)),
                                (12.0, 1.6, "corridor to library (double door)", None)])
    w((30, 18), (36, 18))
    # lockers along the corridor (gaps between banks)
    for u0 in (1.0, 8.5, 15.5):
        b.box(u0, 10.08, u0 + 3.0, 10.42)
    for v0 in (14.8, 23.2):
        b.box(29.6, v0, 29.92, v0 + 2.4)
    # classrooms: table grids
    def tables(u0, v0, nx, ny, du=1.8, dv=1.3):
        for i in range(nx):
            for j in range(ny):
                b.table(u0 + i * du, v0 + j * dv, u0 + i * du + 1.2, v0 + j * dv + 0.6)
                b.chair(u0 + i * du + 0.35, v0 + j * dv - 0.3); b.chair(u0 + i * du + 0.85, v0 + j * dv - 0.3)
    for u0 in (0.8, 7.8, 14.8, 21.8):
        tables(u0 + 0.2, 3.0, 3, 3)
        b.desk(u0 + 0.5, 7.5, u0 + 2.3, 8.3, "s")
    for u0 in (0.8, 8.8):
        tables(u0 + 0.3, 14.8, 3, 3)
    tables(22.3, 21.2, 3, 3)
    tables(31.0, 11.6, 3, 3, 1.6, 1.3)
    b.table(17.2, 15.5, 19.8, 17.0); b.box(16.2, 19.2, 20.8, 19.8)
    for p in [(17.5, 15.1), (18.5, 15.1), (19.5, 15.1), (17.5, 17.4), (18.5, 17.4), (19.5, 17.4)]:
        b.chair(*p)
    # library: shelves rows east-west, aisles 0.85 / 0.8 to a reading corner at the east
    b.box(31.5, 19.5, 34.0, 20.0); b.box(31.5, 20.85, 34.0, 21.35); b.box(31.5, 22.15, 34.0, 22.65)
    b.box(35.4, 18.4, 35.85, 25.6)
    b.passage(32.75, 20.42, 0.85, "library aisle between shelf rows 1 and 2", across=(0, 1))
    b.passage(32.75, 21.75, 0.8, "library aisle between shelf rows 2 and 3", across=(0, 1))
    b.table(31.2, 24.0, 33.0, 25.0)
    b.outside(14)
    b.space(14.0, 11.4, "hallway", "L-shaped corridor", region=(0.5, 10.45, 26.8, 12.7))
    b.space(3.5, 8.8, "room", "classroom 1", region=(0.1, 2.1, 6.9, 9.9))
    b.space(10.5, 8.8, "room", "classroom 2", region=(7.1, 2.1, 13.9, 9.9))
    b.space(17.5, 8.8, "room", "classroom 3", region=(14.1, 2.1, 20.9, 9.9))
    b.space(30.0, 8.0, "room", "toilets", region=(28.1, 6.1, 31.9, 9.9))
    b.space(4.0, 19.0, "room", "classroom 5", region=(0.1, 12.9, 7.9, 19.9))
    b.space(12.0, 19.0, "room", "classroom 6", region=(8.1, 12.9, 15.9, 19.9))
    b.space(18.5, 14.0, "room", "staff room", region=(16.1, 12.9, 20.9, 19.9))
    b.space(24.0, 24.5, "room", "classroom 7", region=(21.1, 20.1, 27.1, 25.9))
    b.space(33.0, 17.0, "room", "classroom 8", region=(30.1, 10.1, 35.9, 17.9))
    b.space(34.7, 23.5, "room", "library", region=(30.1, 18.1, 35.9, 25.9))
    b.route([(0.8, 11.4), (28.6, 11.4), (28.6, 25.0), (28.6, 22.0), (30.5, 22.0), (30.5, 23.4), (34.6, 23.4),
             (34.6, 18.9), (30.6, 18.9), (30.5, 22.0), (28.6, 22.0), (28.6, 11.4), (19.5, 11.4), (19.5, 9.0),
             (20.3, 8.0), (20.3, 3.0), (20.3, 8.0), (19.5, 9.0), (19.5, 11.4), (6.5, 11.4), (6.5, 14.0),
             (7.0, 14.5), (7.0, 19.3), (1.0, 19.3), (0.6, 14.0), (6.5, 14.0), (6.5, 11.4), (0.8, 11.4)])
    return b


def shop():
    b = B("b3_shop_floor", "Shop (28 x 18 m, rotated 7 deg): sales floor with gondola runs (1.8 m aisles; one aisle "
          "narrowed to 0.9 m by a promo stand), wall shelving, three checkouts with 0.9 m lanes (narrow passages) "
          "by a glazed shopfront with a 1.8 m entrance; back store behind a 1.6 m double swing door, a staff "
          "office, a toilet. Hard: gondolas are not rooms, glazed front leaks rays.", (28, 18), theta=7, seed=6)
    w = b.wall
    w((0, 0), (22, 0), EXT, doors=[(15.0, 1.8, "shop entrance (sliding doors open)")], windows=[(0.5, 13.8)])
    w((22, 0), (28, 0), EXT)
    w((28, 0), (28, 18), EXT, doors=[(12.0, 1.2, "back store: delivery door to yard", ("a", 1, 95))])
    w((28, 18), (0, 18), EXT)
    w((0, 18), (0, 0), EXT)
    w((22, 0), (22, 18), doors=[(3.0, 0.9, "sales floor to staff office", ("a", -1, 95)),
                               (11.0, 1.6, "sales floor to back store (double swing door)", ("b", -1, 100))])
    w((22, 6), (28, 6))
    w((25.5, 15), (25.5, 18), doors=[(1.5, 0.8, "back store to toilet", ("a", -1, 95))])
    w((25.5, 15), (28, 15))
    # gondolas (east-west), two blocks
    for u0 in (3.0, 12.5):
        for k in range(4):
            v0 = 6.0 + k * 2.6
            b.box(u0, v0, u0 + 7.5, v0 + 0.8)
    # promo stand narrowing one aisle
    b.box(14.0, 9.6, 16.6, 10.5)
    b.passage(15.3, 10.85, 0.7, "aisle narrowed by a promo stand", across=(0, 1))
    b.box(0.15, 4.0, 0.7, 17.8); b.box(0.7, 17.3, 21.8, 17.85)      # wall shelving
    # checkouts: counters north-south lanes
    for k in range(3):
        u0 = 5.0 + k * 1.65
        b.box(u0, 1.5, u0 + 0.75, 3.6)
    for k in range(2):
        b.passage(5.75 + k * 1.65 + 0.45, 2.55, 0.86, f"checkout lane {k+1}", across=(1, 0))
    b.box(1.0, 2.5, 4.8, 3.0)   # barrier west of checkouts
    b.box(9.8, 2.5, 12.0, 3.0)  # barrier east
    b.passage(9.42, 2.75, 0.75, "gap between the last checkout and the east barrier", across=(1, 0))
    # back store shelving + boxes
    b.box(22.4, 16.8, 25.0, 17.8); b.box(27.0, 6.4, 27.8, 10.0); b.box(23.0, 8.0, 24.2, 9.0)
    b.desk(26.0, 4.8, 27.8, 5.8, "n"); b.chair(26.8, 4.3); b.box(22.3, 0.3, 23.0, 2.0)
    b.outside(12)
    b.space(11.0, 4.8, "room", "sales floor", group="sales", region=(1.0, 3.7, 21.8, 17.0))
    b.space(17.0, 1.6, "room", "entrance zone in front of the checkouts", group="sales", region=(12.5, 0.3, 21.5, 3.5))
    b.space(25.0, 12.0, "room", "back store", region=(22.1, 6.1, 27.9, 14.9))
    b.space(25.0, 3.0, "room", "staff office", region=(22.1, 0.1, 27.9, 5.9))
    b.space(26.8, 16.5, "room", "toilet", region=(25.6, 15.1, 27.9, 17.9))
    b.route([(15.0, 0.9), (14.5, 4.5), (11.5, 5.2), (2.0, 5.0), (2.0, 16.0), (11.5, 16.0), (11.5, 5.2),
             (21.3, 5.2), (21.3, 16.0), (11.5, 16.0), (11.8, 8.2), (11.8, 11.0), (20.8, 11.0), (23.0, 10.9),
             (26.0, 11.0), (26.0, 12.0), (24.0, 14.5), (24.0, 11.0), (23.0, 10.9), (20.8, 11.0), (21.0, 4.0), (21.0, 3.0), (23.5, 3.0),
             (21.0, 3.0), (16.0, 4.5), (6.2, 4.5), (6.2, 1.2), (15.0, 0.8)])
    return b


def lab():
    b = B("b3_lab", "Teaching lab (20 x 14 m, rotated -12 deg): a south corridor (entrance east, door to an "
          "unexplored stair west), a big lab with island benches (solid), fume hoods and a gas-cylinder cage "
          "leaving 0.8 / 0.7 m squeezes, a prep room, a write-up office with a glass wall to the lab. Hard: "
          "benches split the lab visually but it is ONE room; glass wall with a door.", (20, 14), theta=-12,
          seed=7)
    w = b.wall
    w((0, 0), (20, 0), EXT)
    w((20, 0), (20, 14), EXT, doors=[(1.1, 1.2, "corridor east end: entrance door to outside", ("b", -1, 95))])
    w((20, 14), (0, 14), EXT)
    w((0, 14), (0, 0), EXT, doors=[(12.9, 1.0, "corridor west end: door to unexplored stair", ("a", -1, 100))])
    w((0, 2.2), (20, 2.2), doors=[(3.0, 1.4, "corridor to lab (double door)", ("b", 1, 90)),
                                 (11.5, 0.9, "corridor to lab (east door)", ("b", 1, 95)),
                                 (17.0, 0.9, "corridor to write-up office", ("a", 1, 100))])
    w((14, 2.2), (14, 8), glass=True, doors=[(3.0, 0.9, "lab to write-up office (glass wall door)", ("a", -1, 90))])
    w((14, 8), (14, 14), doors=[(3.2, 0.9, "lab to prep room", ("b", -1, 100))])
    w((14, 8), (20, 8))
    w((-6, 0), (-6, 2.2)); w((-6, 2.2), (0, 2.2)); w((-6, 0), (0, 0))   # stair enclosure (unexplored)
    b.box(-4.0, 0.2, -1.0, 1.6)
    # lab benches: two island pairs + wall benches
    for (u0, v0) in [(2.0, 5.0), (2.0, 9.0), (7.5, 5.0), (7.5, 9.0)]:
        b.box(u0, v0, u0 + 3.8, v0 + 1.5)
    b.box(0.15, 3.5, 0.9, 12.8)         # wall bench west
    b.box(1.0, 13.1, 6.0, 13.85)        # fume hoods north
    b.box(7.0, 13.1, 12.0, 13.85)
    b.box(12.2, 9.2, 13.3, 10.6)        # gas-cylinder cage (leaves 0.7 m to the wall)
    b.box(11.4, 12.2, 13.85, 12.9)      # sink bench
    b.passage(13.62, 9.9, 0.64, "squeeze between gas-cylinder cage and the prep-room wall", across=(1, 0))
    b.passage(11.75, 9.9, 0.9, "gap between island bench and gas-cylinder cage", across=(1, 0))
    for (u, v) in [(3.0, 4.6), (4.5, 4.6), (8.5, 4.6), (10.0, 4.6), (3.0, 10.9), (9.0, 10.9)]:
        b.chair(u, v)
    # office + prep
    b.desk(15.0, 6.9, 16.6, 7.8, "n"); b.desk(17.2, 6.9, 18.8, 7.8, "n"); b.chair(15.8, 6.4); b.chair(18.0, 6.4)
    b.box(19.2, 2.5, 19.85, 5.0)
    b.box(14.2, 13.2, 19.8, 13.85); b.box(19.2, 8.3, 19.85, 12.5); b.table(15.5, 10.0, 17.5, 11.0)
    b.outside(10)
    b.space(8.0, 1.1, "hallway", "corridor", region=(0.5, 0.1, 19.5, 2.1))
    b.space(6.5, 7.5, "room", "lab", region=(1.0, 2.3, 13.9, 13.0))
    b.space(17.0, 4.0, "room", "write-up office", region=(14.1, 2.3, 19.9, 7.9))
    b.space(16.5, 12.0, "room", "prep room", region=(14.1, 8.1, 19.9, 13.1))
    b.route([(19.0, 1.1), (0.8, 1.1), (3.0, 1.1), (3.0, 3.5), (1.4, 3.8), (1.4, 12.5), (6.5, 12.5), (6.5, 7.5),
             (11.9, 7.5), (11.9, 11.6), (11.9, 3.5), (13.0, 5.2), (16.0, 5.2), (18.5, 4.0), (17.0, 3.2),
             (17.0, 1.1), (11.5, 1.1), (11.5, 3.8), (11.9, 8.8), (11.9, 10.9), (13.0, 11.0), (15.5, 11.5),
             (13.0, 11.0), (11.9, 10.9), (11.9, 8.8), (11.5, 3.8), (11.5, 1.1), (19.0, 1.1)])
    return b


def flat():
    b = B("b3_flat_angled", "Flat (11 x 10 m, rotated 38 deg) with an irregular living room: its north-east wall "
          "runs at 53 deg and the kitchen/living wall is slanted; hallway with the front door, kitchen, two "
          "bedrooms, bathroom, a balcony door in the slanted facade. A 0.7 m squeeze between the sofa back and a "
          "bookcase leads to the balcony door. Hard: non-rectangular room, slanted walls.", (11, 10), theta=38,
          seed=8)
    b.foot = [(0, 0), (11, 0), (11, 6), (8, 10), (0, 10)]
    w = b.wall
    w((0, 0), (11, 0), EXT)
    w((11, 0), (11, 6), EXT)
    w((11, 6), (8, 10), EXT, doors=[(2.5, 0.9, "living room to balcony (door open)", ("a", -1, 100))])
    w((8, 10), (0, 10), EXT)
    w((0, 10), (0, 0), EXT, doors=[(5.3, 0.95, "front door to stairwell", ("b", -1, 95))])
    w((0, 4), (11, 4), doors=[(2.6, 0.85, "hallway to bedroom 1", ("a", -1, 90)),
                              (5.2, 0.75, "hallway to bathroom", ("b", -1, 100)),
                              (8.9, 0.85, "living room to bedroom 2", ("a", -1, 95))])
    w((4, 0), (4, 4)); w((6.5, 0), (6.5, 4))
    w((0, 5.4), (3.3, 5.4), doors=[(1.8, 0.85, "hallway to kitchen", ("a", 1, 100))])
    w((3.3, 5.4), (4.6, 10))                     # slanted kitchen/living wall, no door
    w((6.0, 4.0), (6.0, 5.4))
    w((3.3, 5.4), (4.8, 5.4))
    w((4.8, 5.4), (6.0, 5.4), doors=[])
    b.doors.append({"center": (6.0, 4.7), "width_m": 1.0, "optional": False, "note": "hallway to living room",
                    "t": (0, 1), "n": (-1, 0)})
    # cut the doorway: re-clear the strip (walls drawn above at u=6 v 4..5.4 are replaced)
    b.cls[int((4.2 - b.tv0) / 0.02):int((5.2 - b.tv0) / 0.02), int((5.9 - b.tu0) / 0.02):int((6.1 - b.tu0) / 0.02)] = 0
    # hallway east end closed by a wall line from (4.8,5.4)-(6,5.4) and the living room beyond u=6
    b.box(0.4, 9.2, 3.2, 9.8); b.box(0.2, 6.0, 0.75, 8.8); b.table(1.3, 6.8, 2.4, 7.8)
    b.chair(1.0, 7.3); b.chair(2.7, 7.3)
    b.box(6.6, 6.6, 8.8, 7.5)                    # sofa
    b.box(7.2, 8.2, 8.55, 8.55)                  # bookcase behind the sofa (0.7 m gap)
    b.passage(7.7, 7.86, 0.66, "squeeze between sofa back and bookcase (to balcony door)", across=(0, 1))
    b.table(7.2, 5.2, 8.2, 5.9)                  # coffee table
    b.box(10.3, 4.2, 10.85, 5.8)                 # tv unit
    b.box(0.2, 0.2, 1.8, 2.2); b.box(6.9, 0.2, 8.5, 2.2); b.box(4.2, 0.2, 4.9, 1.9)
    b.box(10.2, 0.2, 10.85, 2.6)
    b.outside(10)
    b.space(2.0, 4.7, "hallway", "hallway", region=(0.1, 4.1, 5.9, 5.3))
    b.space(2.0, 8.0, "room", "kitchen", region=(0.3, 5.5, 3.9, 9.9))
    b.space(8.0, 5.8, "room", "living room", region=(4.2, 4.1, 10.9, 9.0))
    b.space(2.7, 2.8, "room", "bedroom 1", region=(0.1, 0.1, 3.9, 3.9))
    b.space(5.25, 2.5, "room", "bathroom", region=(4.1, 0.1, 6.4, 3.9))
    b.space(9.3, 2.9, "room", "bedroom 2", region=(6.6, 0.1, 10.9, 3.9))
    b.route([(0.6, 4.7), (5.0, 4.7), (7.0, 4.8), (9.5, 5.0), (9.5, 6.3), (9.2, 7.85), (6.2, 7.85), (5.8, 7.0),
             (7.0, 4.8), (8.9, 4.6), (8.9, 3.0), (8.9, 4.6), (2.6, 4.7), (2.6, 2.8), (2.6, 4.7), (1.8, 4.7),
             (1.8, 6.3), (2.0, 8.4), (1.8, 6.3), (1.8, 4.7), (0.6, 4.7)])
    return b


def partial():
    b = B("b3_partial_offices", "Partially explored office building (32 x 20 m, rotated 8 deg): the robot drove only "
          "the west 2/3 of a 2 m corridor (a copier + cabinet squeeze it to 0.75 m) and two offices. Many doors stand open onto rooms it never entered "
          "(their floor is seen as wedges through the door; rooms seen too little get no point and an ignore "
          "box), others are closed; the corridor's east third is only seen from afar; a stair door at the west "
          "end and a door on the north side open onto unexplored space. Hard: big unknown regions; doors into "
          "unknown are real doors.", (32, 20), theta=8, seed=9)
    w = b.wall
    w((0, 0), (32, 0), EXT); w((32, 0), (32, 20), EXT); w((32, 20), (0, 20), EXT)
    w((0, 20), (0, 0), EXT, doors=[(10.0, 1.0, "corridor west end: door to stair (unexplored)", ("a", 1, 95))])
    sd = []
    for i in range(8):
        u = i * 4 + 2.0
        if i in (2, 6):
            sd.append({"at": u, "w": 0.9, "note": "closed", "closed": True})
        else:
            sd.append((u + (0.6 if i % 2 else -0.6), 0.9, f"corridor to office S{i+1}", ("a", -1, 70 + 9 * i)))
    w((0, 9), (32, 9), doors=sd)
    nd = []
    for i in range(8):
        u = i * 4 + 2.0
        if i in (1, 5):
            nd.append({"at": u, "w": 0.9, "note": "closed", "closed": True})
        else:
            nd.append((u + (0.7 if i % 2 else -0.5), 0.9, f"corridor to office N{i+1}", ("b", 1, 80 + 6 * i)))
    w((0, 11), (32, 11), doors=nd)
    for i in range(1, 8):
        w((i * 4, 0), (i * 4, 9)); w((i * 4, 11), (i * 4, 20))
    for i in range(8):
        b.desk(i * 4 + 0.5, 0.3, i * 4 + 2.1, 1.1, "s"); b.box(i * 4 + 3.3, 4.0, i * 4 + 3.85, 6.0)
        b.desk(i * 4 + 1.5, 18.9, i * 4 + 3.1, 19.7, "n"); b.box(i * 4 + 0.15, 13.0, i * 4 + 0.7, 15.0)
        b.chair(i * 4 + 1.3, 1.6); b.chair(i * 4 + 2.3, 18.4)
    b.box(2.6, 9.1, 3.8, 9.75); b.box(2.7, 10.5, 3.6, 10.9)     # copier + cabinet in the corridor
    b.passage(3.2, 10.12, 0.75, "corridor squeeze between copier and cabinet", across=(0, 1))
    b.outside(8)
    b.space(10.0, 10.0, "hallway", "corridor", region=(0.5, 9.1, 31.5, 10.9))
    for i in range(8):
        if i not in (2, 6):
            b.space(i * 4 + 2.0, 5.0, "room", f"office S{i+1}", region=(i * 4 + 0.1, 0.1, i * 4 + 3.9, 8.9))
        if i not in (1, 5):
            b.space(i * 4 + 2.0, 15.0, "room", f"office N{i+1}", region=(i * 4 + 0.1, 11.1, i * 4 + 3.9, 19.9))
    b.route([(0.8, 10.0), (21.0, 10.0), (17.4, 10.0), (17.4, 7.0), (18.6, 3.0), (17.4, 7.0), (17.4, 10.0),
             (9.5, 10.0), (9.5, 13.0), (10.0, 16.0), (9.5, 13.0), (9.5, 10.0), (0.8, 10.0)])
    return b


def clinic():
    b = B("b3_clinic", "Medical clinic (26 x 14 m, rotated -67 deg): entrance lobby + waiting room (one open room "
          "with fixed bench rows; the 0.74 m gaps between each bench row and the west wall are narrow passages), a "
          "reception counter, a 2 m opening (optional door) into a dog-leg corridor (a 45-degree jog of 1 m halfway: "
          "ONE hallway) with consulting rooms both sides (couches, desks), treatment room, toilets, staff room, "
          "a closed records room. Hard: steep rotation, dog-leg corridor, bench rows.", (26, 14), theta=-67, seed=10)
    w = b.wall
    w((0, 0), (26, 0), EXT)
    w((26, 0), (26, 14), EXT, doors=[(8.0, 0.9, "corridor east end: door to outside", ("a", 1, 95))])
    w((26, 14), (0, 14), EXT)
    w((0, 14), (0, 0), EXT, doors=[(3.0, 1.8, "clinic entrance (double door)", ("a", 1, 90))])
    w((8, 0), (8, 6))
    w((8, 8), (8, 14), doors=[(2.0, 0.9, "waiting room to consulting room 1", ("b", 1, 100))])
    w((8, 6), (16, 6), doors=[(2.0, 0.9, "corridor to consulting room 2", ("a", -1, 95)),
                             (6.0, 0.9, "corridor to consulting room 3", ("b", -1, 90))])
    w((8, 8), (16, 8), doors=[(6.0, 0.9, "corridor to consulting room 4", ("a", 1, 95))])
    w((16, 6), (17, 7)); w((16, 8), (17, 9))
    w((17, 7), (26, 7), doors=[(1.5, 0.9, "corridor to treatment room", ("a", -1, 100)),
                              (4.5, 0.85, "corridor to toilets", ("b", -1, 95)),
                              {"at": 7.5, "w": 0.9, "note": "records", "closed": True}])
    w((17, 9), (26, 9), doors=[(2.0, 0.9, "corridor to consulting room 5", ("b", 1, 100)),
                              (6.5, 0.9, "corridor to staff room", ("a", 1, 90))])
    w((12, 0), (12, 6)); w((16, 0), (16, 6)); w((20, 0), (20, 7)); w((23, 0), (23, 7))
    w((12, 8), (12, 14)); w((16, 8), (16, 14)); w((21, 9), (21, 14))
    b.doors.append({"center": (8.0, 7.0), "width_m": 2.0, "optional": True,
                    "note": "waiting room to corridor (2 m opening)", "t": (0, 1), "n": (1, 0)})
    b.box(4.2, 0.2, 7.8, 1.2)          # reception counter
    b.box(6.9, 1.2, 7.8, 3.0)          # counter return
    for v0 in (5.0, 7.0, 9.0):
        b.box(0.85, v0, 5.8, v0 + 0.55)  # fixed bench rows
    for k, v0 in enumerate((5.0, 7.0, 9.0)):
        b.passage(0.48, v0 + 0.27, 0.74, f"gap between bench row {k+1} and the west wall", across=(1, 0))
    b.box(0.2, 12.9, 3.0, 13.8)        # toy shelf
    for (u0, v0, v1) in [(8, 0, 6), (12, 0, 6)]:
        b.box(u0 + 0.2, v0 + 1.5, u0 + 0.9, v0 + 3.4)
        b.desk(u0 + 2.4, v0 + 0.3, u0 + 3.8, v0 + 1.1, "s")
    for (u0, v0, v1) in [(8, 8, 14), (12, 8, 14), (16, 9, 14)]:
        b.box(u0 + 3.1, v0 + 2.0, u0 + 3.8, v0 + 3.9)
        b.desk(u0 + 0.3, v1 - 1.1, u0 + 1.8, v1 - 0.3, "n")
    b.box(16.2, 0.2, 19.8, 1.0); b.box(18.0, 3.0, 19.0, 5.0)
    b.table(22.5, 11.5, 24.5, 12.5); b.chair(22.1, 12.0); b.chair(24.9, 12.0); b.box(21.2, 13.2, 25.8, 13.8)
    b.outside(12)
    b.space(3.5, 11.3, "room", "entrance lobby + waiting room", region=(0.2, 1.3, 7.2, 13.8))
    b.space(12.0, 7.0, "hallway", "dog-leg corridor", region=(8.5, 6.1, 25.5, 8.9))
    b.space(10.3, 11.0, "room", "consulting room 1", region=(8.1, 8.1, 11.9, 13.9))
    b.space(10.3, 3.5, "room", "consulting room 2", region=(8.1, 0.1, 11.9, 5.9))
    b.space(14.3, 3.5, "room", "consulting room 3", region=(12.1, 0.1, 15.9, 5.9))
    b.space(14.3, 11.0, "room", "consulting room 4", region=(12.1, 8.1, 15.9, 13.9))
    b.space(18.0, 4.0, "room", "treatment room", region=(16.1, 1.1, 19.9, 6.9))
    b.space(21.5, 4.0, "room", "toilets", region=(20.1, 0.1, 22.9, 6.9))
    b.space(18.5, 11.5, "room", "consulting room 5", region=(16.1, 9.1, 20.9, 13.9))
    b.space(23.5, 10.5, "room", "staff room", region=(21.1, 9.1, 25.9, 13.1))
    b.route([(1.0, 3.0), (3.0, 3.5), (6.3, 4.2), (6.4, 10.0), (9.5, 10.0), (6.4, 10.0), (3.5, 11.5), (0.5, 11.0),
             (0.5, 4.0), (6.3, 4.2), (6.5, 6.5), (7.2, 7.0), (10.0, 7.0), (14.0, 7.0), (14.0, 3.0), (14.0, 7.0),
             (16.0, 7.0), (17.0, 8.0), (25.0, 8.0), (23.5, 8.0), (23.5, 10.6), (23.5, 8.0), (18.5, 8.0),
             (18.5, 5.6), (17.3, 5.4), (17.2, 3.5), (17.3, 5.4), (18.5, 5.6), (18.5, 8.0), (17.0, 8.0), (16.0, 7.0), (9.0, 7.0), (6.5, 6.5),
             (6.3, 4.2), (3.0, 3.5), (1.0, 3.0)])
    return b


def restaurant():
    b = B("b3_restaurant", "Restaurant (22 x 15 m, rotated 23 deg): one dining room full of tables (legs) and chairs, "
          "booths, a bar counter whose 0.76 m service gap beside a pillar (narrow passage) leads behind the bar; "
          "a kitchen behind a 1.1 m swing door, a 1.6 m toilet corridor with two WCs (seen through their doors), "
          "a glazed street front with the entrance, a terrace door. Hard: dense chair legs, glazing fans.",
          (22, 15), theta=23, seed=11)
    w = b.wall
    w((0, 0), (22, 0), EXT, doors=[(4.0, 1.6, "restaurant entrance (double door)", ("a", -1, 95))],
      windows=[(6.0, 13.5)])
    w((22, 0), (22, 15), EXT, doors=[(3.2, 1.0, "dining room to terrace", ("b", 1, 90))])
    w((22, 15), (0, 15), EXT)
    w((0, 15), (0, 0), EXT)
    w((0, 10), (22, 10), doors=[(9.0, 1.1, "dining room to kitchen (swing door)", ("a", 1, 95)),
                               (12.6, 1.0, "dining room to toilet corridor")])
    w((11.8, 10), (11.8, 15))
    w((13.4, 10), (13.4, 15), doors=[(1.25, 0.8, "toilet corridor to WC 2", ("a", -1, 95)),
                                    (3.75, 0.8, "toilet corridor to WC 1", ("b", -1, 100))])
    w((13.4, 12.5), (17, 12.5))
    w((17, 10), (17, 15))                        # store room beyond (closed, never seen)
    b.box(16.2, 14.2, 16.85, 14.85); b.box(16.2, 10.15, 16.85, 10.8)   # WC pans
    b.box(0.2, 14.2, 11.6, 14.85); b.box(2.0, 11.8, 7.0, 12.7); b.box(0.2, 10.2, 0.8, 13.5)
    b.box(0.12, 6.8, 6.2, 7.4)       # bar counter (against the west wall)
    b.box(0.2, 9.3, 5.0, 9.85)       # back bar shelving
    b.box(6.98, 6.7, 7.5, 7.5)       # pillar
    b.passage(6.59, 7.1, 0.76, "service gap between bar end and pillar (to behind the bar)", across=(1, 0))
    for k in range(4):
        b.chair(1.5 + k * 1.2, 6.3, 0)
    for (u0, v0) in [(9.0, 2.0), (12.0, 2.0), (15.0, 2.0), (9.0, 5.2), (12.0, 5.2), (15.0, 5.2), (2.0, 2.2),
                     (5.0, 2.2), (9.5, 8.0), (2.0, 4.4)]:
        b.table(u0, v0, u0 + 1.2, v0 + 0.8)
        b.chair(u0 + 0.3, v0 - 0.35); b.chair(u0 + 0.9, v0 - 0.35); b.chair(u0 + 0.3, v0 + 1.15); b.chair(u0 + 0.9, v0 + 1.15)
    for v0 in (4.4, 6.4, 8.4):
        b.box(20.5, v0, 21.85, v0 + 1.5)
    b.box(17.6, 0.2, 19.0, 1.5)      # service station
    b.outside(12)
    b.space(11.0, 4.0, "room", "dining room", group="dining", region=(0.5, 0.5, 20.3, 9.9))
    b.space(3.5, 8.35, "room", "bar zone behind the counter (alcove of the dining room)", group="dining",
            region=(0.3, 7.5, 6.1, 9.2))
    b.space(5.5, 13.2, "room", "kitchen", region=(0.9, 10.1, 11.7, 14.1))
    b.space(12.6, 12.5, "hallway", "toilet corridor", region=(11.9, 10.1, 13.3, 14.9))
    b.space(15.2, 13.75, "room", "WC 1", region=(13.5, 12.6, 16.9, 14.9))
    b.space(15.2, 11.25, "room", "WC 2", region=(13.5, 10.1, 16.9, 12.4))
    b.route([(4.0, 0.8), (4.0, 4.0), (7.5, 4.0), (18.0, 4.0), (19.8, 6.0), (19.8, 9.4), (13.5, 7.4),
             (12.6, 9.65), (12.6, 14.0), (12.6, 9.65), (9.0, 9.65), (9.0, 11.0), (9.0, 13.2), (5.0, 13.3),
             (9.0, 13.2), (9.0, 11.0), (9.0, 9.65), (6.6, 8.2), (3.5, 8.4), (6.6, 8.2), (6.6, 5.8),
             (4.0, 4.0), (4.0, 0.8)])
    return b


BUILDINGS = [home, office, ward, warehouse, school, shop, lab, flat, partial, clinic, restaurant]
