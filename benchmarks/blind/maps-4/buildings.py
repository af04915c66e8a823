"""The blind5 buildings (building frame: u east, v north, metres). See README.md."""
from sim import B

EXT = 0.24


def sports():
    b = B("b5_sports_centre", "Sports centre (34 x 22 m, rotated 23 deg): a 22 x 16 m sports hall (bleachers, "
          "benches, mats, net posts) with a 1.8 m double door and a 1.2 m door onto a 2 m corridor; entrance lobby "
          "(1.8 m double entrance door, 1.6 m double door to the corridor), reception office, men's and women's "
          "changing rooms each with a small shower room behind a 0.8 m doorway, accessible WC, first-aid room, "
          "staff room, closed cleaner's closet; an equipment store behind a 1.8 m double door from the hall; a 0.9 m "
          "service corridor (narrow passage, not a space) from the corridor to the fitness room with a plant room "
          "off it; fitness room with treadmills and a row of machines (0.75 m and 0.62 m gaps = passages). The "
          "return pass has a 7 cm / 0.5 deg loop-closure error (doubled walls). Hard: huge hall vs small rooms, "
          "double doors, narrow service corridor, rooms seen through doors.", (34, 22), theta=23, seed=11)
    w = b.wall
    w((0, 0), (34, 0), EXT, doors=[(2.5, 1.8, "main entrance double door (lobby to outside)", ("d", -1, 95))])
    w((34, 0), (34, 22), EXT, doors=[(5.0, 1.0, "corridor east end: exit door to outside", ("a", -1, 100))])
    w((34, 22), (0, 22), EXT)
    w((0, 22), (0, 0), EXT)
    # south strip v 0..4 (rooms) | corridor v 4..6 | hall + east block v 6..22
    w((0, 4), (34, 4), doors=[(2.5, 1.6, "lobby to corridor (double door)", ("d", 1, 90)),
                             (9.0, 1.0, "corridor to men's changing", ("a", -1, 95)),
                             (19.0, 1.0, "corridor to women's changing", ("b", -1, 100)),
                             (21.2, 0.9, "corridor to accessible WC", ("b", -1, 90)),
                             (24.2, 0.9, "corridor to first-aid room", ("a", -1, 85)),
                             {"at": 26.7, "w": 0.8, "note": "cleaner", "closed": True},
                             (29.0, 0.9, "corridor to staff room", ("a", -1, 100))])
    w((5, 0), (5, 4), doors=[(2.0, 0.9, "lobby to reception office", ("b", -1, 90))])
    for u in (8, 14, 20, 22.5, 26, 27.5):
        w((u, 0), (u, 4))
    w((12, 2.4), (14, 2.4), doors=[(1.0, 0.8, "men's changing to showers")])
    w((12, 0), (12, 2.4))
    w((14, 2.4), (16, 2.4), doors=[(1.0, 0.8, "women's changing to showers")])
    w((16, 0), (16, 2.4))
    w((0, 6), (34, 6), doors=[(4.0, 1.8, "corridor to sports hall (double door)", ("d", 1, 88)),
                             (16.0, 1.2, "corridor to sports hall (single door)", ("a", 1, 95)),
                             (27.45, 0.8, "corridor to service corridor", ("a", 1, 100))])
    w((22, 6), (22, 12), doors=[(3.0, 1.8, "sports hall to equipment store (double door)", ("d", -1, 92))])
    w((22, 12), (22, 22), doors=[(3.0, 1.2, "sports hall to fitness room", ("a", -1, 95))])
    w((26.94, 6), (26.94, 12))
    w((27.96, 6), (27.96, 12), doors=[(4.5, 0.8, "service corridor to plant room", ("a", -1, 90))])
    w((22, 12), (34, 12), doors=[(5.45, 0.8, "service corridor to fitness room", ("b", 1, 95))])
    # lobby / reception
    b.box(0.15, 0.6, 0.55, 3.2)          # bench
    b.box(5.2, 2.8, 7.8, 3.35)           # reception desk
    # changing rooms: benches + lockers
    b.box(8.3, 0.15, 11.6, 0.55); b.box(8.07, 1.2, 8.45, 3.6); b.box(10.2, 1.7, 11.7, 2.05)
    b.box(16.4, 0.15, 19.8, 0.55); b.box(19.55, 1.0, 19.93, 3.0); b.box(16.6, 2.2, 18.2, 2.55)
    b.box(12.2, 0.2, 12.4, 2.2); b.box(14.2, 0.2, 14.4, 2.2)      # shower partitions
    b.box(20.15, 0.15, 20.8, 0.9)        # WC
    b.box(22.65, 0.2, 23.5, 2.2)         # first-aid couch
    b.box(27.7, 0.15, 30.5, 0.75); b.table(31.0, 1.3, 32.6, 2.5)
    for p in [(30.7, 1.9), (32.9, 1.9), (31.8, 3.0)]:
        b.chair(*p)
    # corridor clutter
    b.box(6.5, 4.08, 7.6, 4.45)          # trophy cabinet
    b.box(12.5, 5.6, 13.7, 5.92)         # bench
    # hall
    b.box(4.0, 20.7, 18.0, 21.85)        # bleachers
    b.box(0.15, 8.5, 0.5, 11.5); b.box(0.15, 14.5, 0.5, 17.5)      # benches
    b.box(19.5, 19.0, 21.6, 20.2)        # stacked mats
    b.box(0.6, 13.6, 1.0, 14.4); b.box(21.2, 13.6, 21.6, 14.4)     # hoop posts
    b.dot(11.0, 9.0, 0.05); b.dot(11.0, 19.0, 0.05)                 # net posts
    # store
    b.box(22.2, 6.2, 26.7, 6.8); b.box(26.1, 7.2, 26.75, 11.7); b.box(23.0, 10.6, 24.6, 11.6)
    # plant room
    b.box(30.0, 8.0, 31.5, 9.5); b.box(32.3, 6.3, 33.7, 8.0); b.box(32.5, 9.8, 33.8, 11.7)
    # fitness room: treadmills along the north wall, a row of machines across the room
    for k in range(5):
        b.box(23.0 + k * 1.6, 19.9, 23.85 + k * 1.6, 21.8)
    row = [(22.25, 24.2), (24.95, 26.5), (28.0, 29.6), (30.22, 32.0), (33.2, 33.85)]
    for u0, u1 in row:
        b.box(u0, 16.3, u1, 17.4)
    b.passage(24.575, 16.85, 0.75, "fitness room: gap between two machines", across=(1, 0))
    b.passage(29.91, 16.85, 0.62, "fitness room: gap between two machines (narrow)", across=(1, 0))
    b.passage(27.45, 9.0, 0.9, "0.9 m service corridor (corridor to fitness room)", across=(1, 0))
    b.box(32.6, 12.3, 33.8, 13.4)        # dumbbell rack
    b.outside(14)
    b.space(2.5, 2.0, "room", "entrance lobby", region=(0.6, 0.1, 4.9, 3.9))
    b.space(6.5, 1.5, "room", "reception office", region=(5.1, 0.1, 7.9, 2.7))
    b.space(10.0, 2.6, "room", "men's changing room", region=(8.5, 0.6, 11.9, 3.9))
    b.space(13.0, 1.2, "room", "men's showers", region=(12.4, 0.1, 13.9, 2.3))
    b.space(18.0, 1.4, "room", "women's changing room", region=(16.1, 0.6, 19.5, 3.9))
    b.space(15.0, 1.2, "room", "women's showers", region=(14.4, 0.1, 15.9, 2.3))
    b.space(21.2, 2.2, "room", "accessible WC", region=(20.1, 0.9, 22.4, 3.9))
    b.space(24.6, 2.6, "room", "first-aid room", region=(23.6, 0.1, 25.9, 3.9))
    b.space(30.0, 2.8, "room", "staff room", region=(27.6, 0.8, 33.9, 3.9))
    b.space(10.0, 5.0, "hallway", "main corridor", region=(0.5, 4.1, 33.5, 5.9))
    b.space(11.0, 14.0, "room", "sports hall", region=(0.6, 6.1, 21.9, 20.6))
    b.space(24.5, 9.0, "room", "equipment store", region=(22.1, 6.9, 26.0, 10.5))
    b.space(29.5, 10.5, "room", "plant room", region=(28.1, 6.1, 33.9, 11.9))
    b.space(28.0, 14.5, "room", "fitness room", region=(22.1, 12.1, 33.9, 19.8))
    b.route([(2.5, 0.9), (2.5, 5.0), (4.0, 5.0), (4.0, 7.5), (2.5, 9.0), (2.5, 18.5), (10.0, 18.0),
             (19.0, 18.0), (20.6, 15.0), (23.5, 15.0), (24.6, 14.5), (31.0, 13.8), (27.25, 15.2), (27.25, 18.6),
             (24.575, 18.6), (24.575, 15.5), (23.5, 15.0), (20.6, 15.0), (20.0, 10.0), (21.0, 9.0), (23.2, 9.0), (20.5, 9.0),
             (13.0, 8.0), (16.0, 7.4), (16.0, 5.0), (9.0, 5.0), (9.0, 2.9), (10.5, 2.9), (9.0, 3.1), (9.0, 5.0),
             (27.45, 5.0), (27.45, 10.5), (27.45, 13.2), (27.45, 10.5), (27.45, 5.0), (33.4, 5.0)])
    b.route([(33.4, 5.0), (24.2, 5.0), (24.2, 2.8), (24.2, 5.0), (2.3, 5.0), (2.5, 1.0)], bias=(0.07, -0.04, 0.5))
    return b


def hotel():
    b = B("b5_hotel", "Small hotel ground floor (30 x 18 m, rotated -14 deg): lobby behind a glass front with a 1.8 m "
          "double entrance door, pillars, reception counter, sofas; restaurant through a 1.8 m double door (tables "
          "and chairs, buffet counter leaving a 0.74 m squeeze to the kitchen wall, street windows); kitchen behind a "
          "1.0 m swing door (island aisle 0.85 m); housekeeping room; a 1.8 m guest corridor with a lift lobby "
          "opening off its west end (grouped with the corridor), six guest rooms (two closed) each with an entry "
          "passage and an en-suite bathroom behind a 0.7 m door; east fire exit. The second pass has a loop-closure "
          "error (doubled corridor walls). Hard: glass front, wedge rooms, small bathrooms, corridor + lift lobby.",
          (30, 18), theta=-14, seed=12)
    w = b.wall
    w((0, 0), (12, 0), glass=True, doors=[(6.0, 1.8, "main entrance (glass double door) to outside", ("d", -1, 90))])
    w((12, 0), (30, 0), EXT, windows=[(1.5, 4.5), (5.5, 8.5)])
    w((30, 0), (30, 18), EXT, doors=[(10.9, 1.0, "corridor east end: fire exit to outside", ("a", -1, 95))])
    w((30, 18), (0, 18), EXT)
    w((0, 18), (0, 0), EXT)
    w((12, 0), (12, 10), doors=[(3.0, 1.8, "lobby to restaurant (double door)", ("d", -1, 90))])
    w((22, 0), (22, 10), doors=[(5.5, 1.0, "restaurant to kitchen (swing door)", ("a", -1, 100))])
    w((22, 7), (30, 7))
    w((0, 10), (30, 10), doors=[(9.0, 1.6, "lobby to guest corridor (double door)", ("d", -1, 90)),
                               (24.0, 0.9, "corridor to housekeeping room", ("b", -1, 95))])
    rdoors = []
    for i, u0 in enumerate((6, 10, 14, 18, 22, 26)):
        if i in (2, 4):
            rdoors.append({"at": u0 - 6 + 0.75, "w": 0.85, "note": f"guest room {i+1}", "closed": True})
        else:
            rdoors.append((u0 - 6 + 0.75, 0.85, f"corridor to guest room {i+1}", ("a", 1, 80 + 6 * i)))
    w((6, 11.8), (30, 11.8), doors=rdoors)
    w((0, 14.5), (6, 14.5))
    w((6, 11.8), (6, 18))
    for u0 in (6, 10, 14, 18, 22, 26):
        if u0 > 6:
            w((u0, 11.8), (u0, 18))
        w((u0 + 1.5, 11.8), (u0 + 1.5, 14.2), doors=[(1.4, 0.7, f"guest room {(u0 - 6) // 4 + 1} to bathroom",
                                                     ("a", -1, 90))] if u0 not in (14, 22) else [])
        w((u0 + 1.5, 14.2), (u0 + 4, 14.2))
        b.box(u0 + 0.6, 16.0, u0 + 2.4, 17.88)     # bed
        b.box(u0 + 3.4, 14.5, u0 + 3.92, 15.8)     # desk
        b.box(u0 + 3.3, 12.0, u0 + 3.9, 12.5)      # basin
    # lobby
    b.box(0.8, 5.5, 1.5, 9.0); b.box(1.5, 8.3, 3.2, 9.0)          # reception counter (L)
    b.box(3.8, 3.8, 4.3, 4.3); b.box(7.8, 3.8, 8.3, 4.3)          # pillars
    b.box(5.2, 6.5, 7.5, 7.3); b.box(9.5, 5.5, 10.3, 7.5)         # sofas
    b.table(5.5, 5.2, 7.0, 5.9)
    b.box(10.8, 8.6, 11.6, 9.7)                                   # luggage trolley
    b.box(0.2, 12.0, 0.6, 13.8)                                   # bench in the lift lobby
    # restaurant
    b.box(17.0, 3.0, 21.2, 3.8)                                   # buffet counter
    b.passage(21.57, 3.4, 0.74, "squeeze between buffet counter and kitchen wall", across=(1, 0))
    for u0 in (13.6, 16.2, 18.8):
        for v0 in (6.0, 8.2):
            b.table(u0, v0, u0 + 1.0, v0 + 0.9)
            b.chair(u0 - 0.35, v0 + 0.45); b.chair(u0 + 1.35, v0 + 0.45)
    b.table(13.2, 0.8, 14.2, 1.5); b.chair(13.7, 1.9)
    # kitchen
    b.box(22.2, 0.15, 29.8, 0.75); b.box(24.0, 1.6, 28.0, 2.6); b.box(29.2, 3.0, 29.85, 6.8)
    b.box(22.5, 6.3, 26.0, 6.85)
    b.passage(26.0, 1.175, 0.85, "kitchen aisle between island and counter", across=(0, 1))
    # housekeeping
    b.box(26.5, 7.2, 29.8, 7.8); b.box(22.3, 7.3, 23.2, 8.5)
    b.outside(14)
    b.space(6.0, 2.0, "room", "lobby", region=(1.6, 0.2, 11.9, 9.9))
    b.space(14.8, 2.6, "room", "restaurant", region=(12.1, 0.1, 21.9, 9.9))
    b.space(25.0, 4.5, "room", "kitchen", region=(22.1, 2.7, 29.1, 6.2))
    b.space(26.0, 8.8, "room", "housekeeping room", region=(22.1, 7.9, 29.9, 9.9))
    b.space(16.0, 10.9, "hallway", "guest corridor", group="corridor", region=(7.0, 10.1, 29.5, 11.7))
    b.space(3.0, 13.0, "hallway", "lift lobby at the corridor's west end", group="corridor",
            region=(0.7, 11.9, 5.9, 14.4))
    for i, u0 in enumerate((6, 10, 14, 18, 22, 26)):
        if i in (2, 4):
            continue
        b.space(u0 + 2.0, 15.1, "room", f"guest room {i+1}", region=(u0 + 0.1, 14.3, u0 + 3.9, 17.9))
        b.space(u0 + 2.75, 13.0, "room", f"bathroom of guest room {i+1}", region=(u0 + 1.6, 11.9, u0 + 3.9, 14.1))
    b.route([(6.0, 1.0), (6.0, 2.5), (10.5, 2.5), (10.5, 3.0), (13.2, 3.0), (14.5, 4.6), (21.2, 4.6), (21.2, 5.5),
             (23.5, 5.5), (23.3, 4.0), (23.3, 1.175), (28.6, 1.175), (28.6, 4.0), (23.3, 4.0), (23.5, 5.5), (21.2, 5.5), (21.2, 4.6), (14.0, 4.6),
             (13.2, 3.0), (10.5, 3.0), (8.9, 4.8), (9.0, 9.2), (9.0, 10.9), (6.75, 10.9), (6.75, 15.0), (8.6, 15.2),
             (6.75, 15.0), (6.75, 10.9), (3.0, 12.8), (3.0, 10.9), (18.75, 10.9), (18.75, 12.9), (18.75, 10.9), (29.3, 10.9)])
    b.route([(29.3, 10.9), (24.0, 10.9), (24.0, 9.2), (24.0, 10.9), (9.0, 10.9), (9.0, 8.5), (8.9, 4.8),
             (9.0, 2.5), (6.0, 1.0)], bias=(-0.06, 0.07, -0.6))
    return b


def library():
    b = B("b5_library", "Public library (26 x 20 m, rotated 35 deg): foyer with lockers and a cloakroom, a 1.8 m double "
          "door into one big L-shaped hall = reading area (tables, chairs, circulation desk) + eight 10.5 m book-stack "
          "rows with aisles of 1.2, 0.8, 0.9, 0.75, 1.2, 0.85 and 1.0 m (the 0.75-0.9 m aisles are narrow passages, "
          "1.0 m optional) + periodicals corner with wall shelving (two grouped points), three glass-fronted study "
          "rooms, staff office, toilet, closed archive; fire exit east. Loop-closure error on the return pass. Hard: "
          "stack rows must not become rooms or doors, glass fronts, long narrow aisles.", (26, 20), theta=35, seed=13)
    w = b.wall
    w((0, 0), (26, 0), EXT, doors=[(2.75, 1.6, "entrance double door (foyer to outside)", ("d", -1, 90))])
    w((26, 0), (26, 20), EXT, doors=[(13.8, 1.0, "fire exit (hall to outside)", ("a", -1, 100))])
    w((26, 20), (0, 20), EXT)
    w((0, 20), (0, 0), EXT)
    w((0, 5), (8, 5), doors=[(2.75, 1.8, "foyer to library hall (double door)", ("d", 1, 85))])
    w((5.5, 0), (5.5, 5), doors=[(2.5, 0.9, "foyer to cloakroom", ("a", -1, 90))])
    w((8, 0), (8, 5))
    w((0, 15), (10.5, 15), glass=True, doors=[(1.75, 0.9, "hall to study room 1 (glass front)", ("a", 1, 90)),
                                             (5.25, 0.9, "hall to study room 2 (glass front)", ("b", 1, 95)),
                                             (8.75, 0.9, "hall to study room 3 (glass front)", ("a", 1, 85))])
    w((10.5, 15), (26, 15), doors=[(1.5, 0.9, "hall to staff office", ("a", 1, 95)),
                                  (5.7, 0.8, "hall to toilet", ("b", 1, 90)),
                                  {"at": 9.5, "w": 1.0, "note": "archive", "closed": True}])
    for u in (3.5, 7.0, 10.5, 15.0, 17.5):
        w((u, 15), (u, 20))
    # foyer / cloakroom
    b.box(0.15, 0.8, 0.55, 4.2); b.box(4.6, 0.3, 5.3, 0.9); b.box(7.3, 0.5, 7.8, 4.5)
    # reading area
    b.box(4.5, 6.0, 7.0, 6.6)            # circulation desk
    for u0 in (1.0, 4.5):
        for v0 in (8.5, 11.0):
            b.table(u0, v0, u0 + 2.4, v0 + 1.0)
            for du in (0.6, 1.8):
                b.chair(u0 + du, v0 - 0.35); b.chair(u0 + du, v0 + 1.35)
    # stacks
    rows = [10.0, 11.7, 13.0, 14.4, 15.65, 17.35, 18.7, 20.2]
    for u in rows:
        b.box(u, 2.0, u + 0.5, 12.5)
    for k, (a, c) in enumerate(zip(rows, rows[1:])):
        gap = round(c - a - 0.5, 2)
        if gap <= 1.0:
            b.passage((a + 0.5 + c) / 2, 7.25, gap, f"book-stack aisle {k+1} ({gap} m)", across=(1, 0),
                      optional=gap >= 1.0)
    # periodicals corner
    b.box(25.35, 1.0, 25.85, 12.5)       # wall shelving
    b.box(22.2, 6.2, 23.0, 8.2)          # display table
    b.box(24.3, 4.0, 25.0, 4.8); b.box(24.3, 9.0, 25.0, 9.8)     # lounge chairs
    # study rooms / office / toilet
    for u0 in (0, 3.5, 7.0):
        b.table(u0 + 1.0, 17.3, u0 + 2.5, 18.3)
        b.chair(u0 + 1.4, 16.9); b.chair(u0 + 2.1, 18.7)
    b.desk(11.0, 18.8, 12.8, 19.7, "n"); b.chair(11.9, 18.3); b.box(14.3, 15.5, 14.85, 19.5)
    b.box(15.2, 19.0, 15.9, 19.8)
    b.outside(14)
    b.space(2.75, 2.5, "room", "foyer", region=(0.6, 0.2, 5.4, 4.9))
    b.space(6.4, 2.5, "room", "cloakroom", region=(5.6, 0.2, 7.2, 4.9))
    b.space(3.0, 7.2, "room", "library hall: reading area", group="hall", region=(0.2, 5.1, 9.8, 14.9))
    b.space(23.5, 3.0, "room", "library hall: periodicals corner", group="hall", region=(21.0, 0.2, 25.2, 14.8))
    b.space(1.75, 17.0, "room", "study room 1 (glass front barely mapped)", group="hall", region=(0.1, 15.1, 3.4, 19.9))
    b.space(5.25, 17.0, "room", "study room 2 (glass front barely mapped)", group="hall", region=(3.6, 15.1, 6.9, 19.9))
    b.space(8.75, 17.0, "room", "study room 3 (glass front barely mapped)", group="hall", region=(7.1, 15.1, 10.4, 19.9))
    b.space(12.5, 16.8, "room", "staff office", region=(10.6, 15.1, 14.2, 18.2))
    b.space(16.25, 17.0, "room", "toilet", region=(15.1, 15.1, 17.4, 18.9))
    b.route([(2.75, 1.0), (2.75, 2.5), (6.6, 2.5), (2.75, 2.5), (2.75, 5.8), (3.0, 7.3), (8.5, 7.3), (8.8, 13.8),
             (23.5, 13.8), (23.5, 1.2), (21.0, 1.0), (18.275, 1.0), (18.275, 13.8), (12.6, 13.8), (12.6, 1.0),
             (9.2, 1.0), (9.2, 13.8), (5.25, 13.8), (5.25, 16.2), (5.25, 13.8), (12.0, 13.8), (12.0, 16.6),
             (12.0, 13.8), (25.5, 13.8)])
    b.route([(25.5, 13.8), (16.2, 13.8), (16.2, 14.6), (16.2, 13.8), (2.75, 13.8), (0.5, 13.0), (0.5, 6.5), (2.75, 6.9),
             (2.75, 5.8), (2.75, 1.0)], bias=(0.05, 0.06, 0.45))
    return b


def garage():
    b = B("b5_parking_garage", "Underground parking level (40 x 30 m, rotated 8 deg): one parking floor (two grouped "
          "points: the south and north drive aisles, which meet at both ends) with parked cars (solid boxes) along "
          "both long walls and a central island of nose-to-nose cars split by a barrier wall with pillars; a 0.85 m "
          "pedestrian crossing slot through the island (passage) and a 0.71 m squeeze between a parked car and the "
          "wall leading to the plant-room door (passage); car gaps against walls/barrier are dead-end slots (not "
          "passages); a 5 m vehicle entrance in the east wall (not a door: too wide) with a big fan; stairwells A "
          "and B, a glass-fronted lift lobby (1.2 m door), a bin store (1.6 m double door), plant room, pedestrian "
          "exit north. Hard: cars look like small rooms/walls, the island splits the floor, pillars.",
          (40, 30), theta=8, seed=14)
    w = b.wall
    X = EXT + 0.06
    w((0, 0), (40, 0), X)
    w((40, 0), (40, 8), X); w((40, 13), (40, 30), X)          # 5 m vehicle entrance (v 8..13)
    w((40, 30), (0, 30), X, doors=[(18.0, 1.0, "pedestrian exit (north) to outside", ("a", 1, 95))])
    w((0, 30), (0, 0), X)
    w((4, 0), (4, 6), 0.2, doors=[(4.8, 1.0, "garage to stairwell A", ("a", -1, 95))])
    w((0, 6), (4, 6), 0.2)
    w((4, 12), (4, 18), glass=True, doors=[(3.0, 1.2, "garage to lift lobby (glass front)")])
    w((0, 12), (4, 12), 0.2); w((0, 18), (4, 18), 0.2)
    w((4, 24), (4, 30), 0.2, doors=[(3.0, 1.6, "garage to bin store (double door)", ("d", 1, 95))])
    w((0, 24), (4, 24), 0.2)
    w((34, 24), (34, 30), 0.2, doors=[(2.0, 1.0, "garage to plant room", ("a", -1, 100))])
    w((34, 24), (40, 24), 0.2)
    w((36, 0), (36, 5), 0.2, doors=[(3.8, 1.0, "garage to stairwell B", ("b", -1, 95))])
    w((36, 5), (40, 5), 0.2)
    # stairwells, lift lobby, bin store, plant room contents
    b.box(0.3, 0.3, 1.6, 3.8); b.box(2.2, 0.3, 3.7, 3.0)
    b.box(36.3, 0.3, 39.7, 1.6)
    b.box(0.15, 13.0, 0.5, 14.2)
    b.box(0.3, 28.5, 3.5, 29.7); b.box(0.3, 24.3, 1.3, 25.3)
    b.box(36.5, 27.5, 39.7, 29.7); b.box(38.0, 24.3, 39.7, 26.0)
    # barrier + pillars through the middle, pedestrian gap at u 18
    b.seg((6.0, 15.1), (17.55, 15.1), 0.15); b.seg((18.45, 15.1), (31.0, 15.1), 0.15)
    for u in (6, 12, 24, 30):
        b.box(u - 0.25, 14.85, u + 0.25, 15.35)
    def car(u0, v0, v1):
        b.box(u0, v0, u0 + 1.85, v1)
    west = [17.575 - 1.85 - 2.6 * k for k in range(5)]
    east = [18.425 + 2.6 * k for k in range(5)]
    for i, u0 in enumerate(west + east):
        if i != 7:
            car(u0, 10.4, 14.7)
        if i != 3:
            car(u0, 15.5, 19.8)
    for k in range(11):
        u0 = 5.375 + 2.6 * k
        if k not in (3, 7):
            car(u0, 0.25, 4.85)
        if k not in (2, 6, 7):
            car(u0, 25.3, 29.75)
    b.passage(18.0, 12.5, 0.85, "pedestrian crossing slot through the central car island", across=(1, 0))
    b.passage(33.58, 26.5, 0.71, "squeeze between a parked car and the plant-room wall", across=(1, 0))
    b.outside(16)
    b.space(20.0, 7.7, "room", "parking floor (south aisle)", group="level", region=(4.5, 5.1, 35.5, 10.2))
    b.space(20.0, 22.5, "room", "parking floor (north aisle)", group="level", region=(4.5, 20.0, 33.5, 25.1))
    b.space(2.8, 4.8, "room", "stairwell A", region=(0.1, 3.1, 3.9, 5.9))
    b.space(38.2, 3.3, "room", "stairwell B", region=(36.1, 1.7, 39.9, 4.9))
    b.space(2.0, 15.0, "room", "lift lobby (glass front barely mapped: grouped with the floor)", group="level", region=(0.6, 12.1, 3.9, 17.9))
    b.space(2.2, 26.9, "room", "bin store", region=(0.1, 25.4, 3.9, 28.4))
    b.space(36.0, 25.8, "room", "plant room", region=(34.1, 24.1, 37.9, 27.4))
    b.route([(38.0, 10.5), (34.0, 7.7), (4.7, 7.7), (4.7, 4.8), (2.6, 4.8), (4.7, 4.8), (4.7, 7.7), (4.7, 15.0),
             (2.0, 15.0), (4.7, 15.0), (5.0, 22.5), (22.0, 22.5), (22.0, 29.3), (22.0, 22.5), (32.5, 22.5),
             (33.58, 23.4), (33.58, 26.0), (35.6, 26.0), (33.58, 26.0), (33.58, 23.4), (38.0, 22.5), (38.0, 6.5),
             (35.0, 6.5), (35.0, 3.8), (37.2, 3.8), (35.0, 3.8), (35.0, 7.7), (38.0, 10.5)])
    b.route([(38.0, 10.5), (36.5, 12.0), (36.5, 22.4), (18.0, 22.4), (18.0, 20.3), (18.0, 22.4), (5.0, 22.4),
             (5.0, 27.0), (2.5, 27.0), (5.0, 27.0), (5.0, 22.4), (4.6, 9.0), (18.0, 7.5), (18.0, 9.9), (30.0, 7.6)],
            bias=(0.08, 0.05, 0.4))
    return b


def mall():
    b = B("b5_mall", "Shopping-mall wing (46 x 22 m, rotated -41 deg): a 6 m concourse (ONE hallway) with kiosks, "
          "planters, benches and café tables; glass entrance double door west, double door east; shops south: "
          "fashion (3 m open glass front: optional, wider than a door), pharmacy (glass, 1.8 m sliding door), "
          "electronics (1.6 m double door), café (glass front, 1.6 m door), bookshop (1.8 m double door, 0.85 m "
          "aisle between gondolas = passage), closed vacant unit; north: department store (glass, 1.9 m), two WCs "
          "(0.9 m doors), toy shop (1.8 m double door, gondola aisles 0.8 m = passages), phone shop (4 m open front: "
          "optional), management office with an inner office; a 1.3 m service corridor behind the north shops with "
          "back doors and a west exit. Return pass with loop-closure error. Hard: glass shopfronts, very wide "
          "openings that are not doors, clutter in the concourse, steep rotation.", (46, 22), theta=-41, seed=15)
    w = b.wall
    I = 0.15
    w((0, 0), (46, 0), EXT)
    w((46, 0), (46, 22), EXT, doors=[(11.0, 1.8, "east mall entrance (double door) to outside", ("d", -1, 90))])
    w((46, 22), (0, 22), EXT)
    w((0, 22), (0, 14), EXT, doors=[(0.75, 1.0, "service corridor west exit to outside", ("a", -1, 95))])
    w((0, 14), (0, 8), glass=True, doors=[(3.0, 1.8, "west mall entrance (glass double sliding door) to outside")])
    w((0, 8), (0, 0), EXT)
    # south shop fronts (v = 8)
    w((0, 8), (8, 8), glass=True, doors=[(4.0, 3.0, "mall to fashion shop: 3 m open glass front (wider than a door)",
                                          None, True)])
    w((8, 8), (14, 8), glass=True, doors=[(3.0, 1.8, "mall to pharmacy (glass sliding double door)")])
    w((14, 8), (22, 8), I, doors=[(4.0, 1.6, "mall to electronics shop (double door)", ("d", -1, 90))])
    w((22, 8), (30, 8), glass=True, doors=[(2.0, 1.6, "mall to café (glass front door)", ("a", -1, 90))])
    w((30, 8), (38, 8), I, doors=[(4.0, 1.8, "mall to bookshop (double door)", ("d", -1, 92))])
    w((38, 8), (46, 8), I)
    for u in (8, 14, 22, 30, 38):
        w((u, 0), (u, 8), I)
    # north fronts (v = 14)
    w((0, 14), (10, 14), glass=True, doors=[(5.0, 1.9, "mall to department store (glass front, 1.9 m opening)")])
    w((10, 14), (13, 14), I, doors=[(1.5, 0.9, "mall to men's WC", ("a", 1, 90))])
    w((13, 14), (16, 14), I, doors=[(1.5, 0.9, "mall to women's WC", ("b", 1, 90))])
    w((16, 14), (26, 14), I, doors=[(5.0, 1.8, "mall to toy shop (double door)", ("d", 1, 90))])
    w((26, 14), (34, 14), I, doors=[(4.0, 4.0, "mall to phone shop: 4 m open front (wider than a door)", None, True)])
    w((34, 14), (46, 14), I, doors=[(3.0, 1.0, "mall to management office", ("a", 1, 95))])
    for u in (10, 13, 16, 26, 34):
        w((u, 14), (u, 20.5), I)
    w((42, 14), (42, 20.5), 0.12, doors=[(3.0, 0.9, "management office to inner office", ("a", -1, 90))])
    w((0, 20.5), (46, 20.5), I, doors=[(5.0, 0.9, "department store back door to service corridor", ("a", -1, 95)),
                                      (21.0, 1.0, "toy shop back door to service corridor", ("a", -1, 100)),
                                      (30.0, 0.9, "phone shop back door to service corridor", ("a", -1, 90))])
    # shops' contents
    b.box(0.2, 0.15, 7.8, 0.6); b.box(1.5, 2.6, 2.7, 3.4); b.box(5.0, 2.6, 6.2, 3.4)
    for p in [(2.0, 5.5), (6.0, 5.5)]:
        b.dot(*p, 0.05)
    b.box(8.2, 0.8, 13.8, 1.4); b.box(9.0, 2.6, 13.0, 3.1)
    b.box(14.2, 0.5, 14.7, 7.5); b.box(15.5, 2.5, 17.5, 3.5); b.box(19.0, 2.5, 21.0, 3.5)
    b.box(28.2, 1.0, 29.8, 6.0)
    for u0, v0 in [(23.0, 2.0), (25.5, 2.0), (23.0, 4.8), (25.5, 4.8)]:
        b.table(u0, v0, u0 + 0.8, v0 + 0.8); b.chair(u0 - 0.3, v0 + 0.4); b.chair(u0 + 1.1, v0 + 0.4)
    b.box(30.2, 0.15, 37.8, 0.6); b.box(31.0, 2.6, 36.5, 3.1); b.box(31.0, 3.95, 36.5, 4.45)
    b.passage(33.75, 3.525, 0.85, "bookshop aisle between two gondolas", across=(0, 1))
    b.box(0.3, 19.6, 4.0, 20.3); b.box(6.0, 19.6, 9.0, 20.3); b.box(2.0, 16.5, 3.5, 17.3); b.box(6.5, 16.5, 8.0, 17.3)
    b.box(10.2, 18.5, 10.7, 20.3); b.box(15.3, 18.5, 15.8, 20.3)
    for u in (17.5, 19.4, 20.7, 22.6, 23.9):
        b.box(u, 15.5, u + 0.5, 19.5)
    b.passage(20.3, 17.5, 0.8, "toy shop: aisle between gondolas (0.8 m)", across=(1, 0))
    b.passage(23.5, 17.5, 0.8, "toy shop: aisle between gondolas (0.8 m)", across=(1, 0))
    b.box(27.0, 16.5, 29.0, 17.3); b.box(31.5, 19.5, 33.8, 20.3)
    b.desk(36.0, 18.8, 37.8, 19.7, "n"); b.chair(36.9, 18.3); b.box(34.2, 14.3, 34.7, 16.5)
    b.desk(43.5, 19.0, 45.3, 19.8, "n"); b.chair(44.4, 18.5)
    # concourse clutter
    b.box(16.5, 10.2, 19.0, 11.8); b.box(35.5, 10.2, 38.0, 11.8)      # kiosks
    b.box(12.0, 10.5, 13.0, 11.5); b.box(31.0, 10.6, 32.0, 11.6)      # planters
    b.box(26.5, 11.0, 28.5, 11.4); b.box(6.0, 13.3, 8.0, 13.7)       # benches
    for u0 in (25.5, 27.5):
        b.table(u0, 8.7, u0 + 0.8, 9.4); b.chair(u0 + 0.4, 9.8)
    b.outside(16)
    b.space(8.0, 11.0, "hallway", "mall concourse", group="concourse", region=(1.0, 8.2, 45.0, 13.8))
    b.space(4.0, 5.0, "room", "fashion shop (glass front barely mapped)", group="concourse", region=(0.2, 3.5, 7.9, 7.9))
    b.space(11.0, 4.5, "room", "pharmacy (glass front barely mapped)", group="concourse", region=(8.1, 3.2, 13.9, 7.9))
    b.space(18.0, 5.5, "room", "electronics shop", region=(14.8, 3.6, 21.9, 7.9))
    b.space(26.0, 6.6, "room", "café (glass front barely mapped)", group="concourse", region=(22.1, 0.1, 28.1, 7.9))
    b.space(34.0, 6.0, "room", "bookshop", region=(30.1, 4.5, 37.9, 7.9))
    b.space(5.0, 15.5, "room", "department store (glass front barely mapped)", group="concourse", region=(0.1, 14.1, 9.9, 19.5))
    b.space(11.5, 17.0, "room", "men's WC", region=(10.1, 14.1, 12.9, 20.4))
    b.space(14.5, 17.0, "room", "women's WC", region=(13.1, 14.1, 15.9, 20.4))
    b.space(22.0, 15.0, "room", "toy shop", region=(16.1, 14.1, 25.9, 20.4))
    b.space(30.0, 15.5, "room", "phone shop", region=(26.1, 14.1, 33.9, 20.4))
    b.space(38.0, 16.0, "room", "management office", region=(34.8, 14.1, 41.9, 18.2))
    b.space(44.0, 16.5, "room", "inner office", region=(42.1, 14.1, 45.9, 18.4))
    b.space(23.0, 21.25, "hallway", "service corridor", region=(0.5, 20.6, 45.5, 21.9))
    b.route([(1.0, 11.0), (4.0, 11.0), (4.0, 9.0), (4.0, 5.0), (4.0, 9.0), (8.0, 11.0), (14.0, 12.5), (21.0, 12.5),
             (21.0, 15.0), (22.0, 15.3), (22.0, 19.9), (21.0, 20.0), (21.0, 21.25), (5.0, 21.25), (5.0, 19.5),
             (5.0, 21.25), (30.0, 21.25), (30.0, 19.0), (30.0, 21.25), (45.3, 21.25), (30.0, 21.25), (30.0, 16.0),
             (30.0, 12.5), (34.0, 12.5), (34.0, 9.0), (34.0, 6.0), (30.6, 6.0), (30.6, 3.525), (37.2, 3.525),
             (37.2, 6.0), (34.0, 6.0), (34.0, 9.0), (34.0, 12.8), (39.0, 12.8), (45.3, 11.0)])
    b.route([(45.3, 11.0), (40.0, 12.6), (37.0, 12.8), (37.0, 14.8), (37.0, 12.8), (24.0, 12.6), (24.0, 9.0),
             (24.0, 6.3), (24.0, 9.0), (24.0, 12.6), (11.0, 12.4), (11.0, 9.0), (11.0, 4.6), (11.0, 9.0),
             (1.0, 11.0)], bias=(-0.12, -0.08, 0.5))
    return b


def icu():
    b = B("b5_icu_ring", "Intensive-care unit (28 x 24 m, rotated 12 deg): a 2.2 m RING corridor (one hallway) around "
          "a central core (nurses' station with a 1.6 m open counter doorway, medication room, staff room, supply "
          "store with a 1.2 m double door, dirty utility, doctors' office); five ICU bays south and three north "
          "(south: solid fronts with small windows; north: full glass fronts that the map barely shows, so bays N1-N3 "
          "are grouped with the corridor) with 1.8 m sliding openings, an isolation room "
          "with a 1.2 m door, a closed bay; west block: waiting room (1.6 m double doors to outside and to the "
          "corridor), relatives' room, equipment store (1.4 m door); a linen trolley and a crash cart squeeze the "
          "west leg to 0.7 m (passage). Second lap with loop-closure error. Hard: a ring corridor must stay ONE "
          "space around the core, glass fronts with many openings, rooms seen only through glass.",
          (28, 24), theta=12, seed=16)
    w = b.wall
    I = 0.15
    w((0, 0), (28, 0), EXT)
    w((28, 0), (28, 24), EXT, doors=[(12.0, 1.2, "ring corridor east leg: fire exit to outside", ("a", -1, 95))])
    w((28, 24), (0, 24), EXT)
    w((0, 24), (0, 0), EXT, doors=[(12.0, 1.6, "main entrance double door (waiting room to outside)", ("d", 1, 90))])
    w((6, 0), (6, 24), I, doors=[(6.0, 0.9, "corridor to relatives' room", ("a", 1, 95)),
                                (12.0, 1.6, "corridor to waiting room (double door)", ("d", 1, 90)),
                                (18.0, 1.4, "corridor to equipment store", ("a", 1, 95))])
    w((0, 8), (6, 8), I); w((0, 16), (6, 16), I)
    w((6, 4.8), (28, 4.8), I, doors=[(2.2 + 4.4 * k, 1.8, f"corridor to ICU bay S{k + 1} (1.8 m sliding door)")
                                     for k in range(5)],
      windows=[x for k in range(5) for x in ((4.4 * k + 0.4, 4.4 * k + 0.9), (4.4 * k + 3.5, 4.4 * k + 4.0))])
    w((6, 19.2), (19.2, 19.2), glass=True, doors=[(2.2 + 4.4 * k, 1.8, f"corridor to ICU bay N{k + 1} (glass sliding door)")
                                                  for k in range(3)])
    w((19.2, 19.2), (28, 19.2), I, doors=[(2.2, 1.2, "corridor to isolation room N4", ("a", 1, 90)),
                                         {"at": 6.6, "w": 1.2, "note": "N5", "closed": True}])
    for u in (10.4, 14.8, 19.2, 23.6):
        w((u, 0), (u, 4.8)); w((u, 19.2), (u, 24))
    # core
    w((8.2, 7), (25.8, 7), I, doors=[(6.8, 1.6, "corridor to nurses' station (open counter doorway)")])
    w((8.2, 17), (25.8, 17), I, doors=[(2.8, 1.2, "corridor to supply store (double door)", ("d", -1, 90)),
                                      (8.3, 0.9, "corridor to dirty utility", ("a", -1, 95)),
                                      (14.3, 0.9, "corridor to doctors' office", ("b", -1, 90))])
    w((8.2, 7), (8.2, 17), I, doors=[(2.0, 0.9, "corridor to medication room", ("a", -1, 95))])
    w((25.8, 7), (25.8, 17), I, doors=[(2.0, 0.9, "corridor to staff room", ("b", 1, 95))])
    w((8.2, 11), (25.8, 11)); w((12, 7), (12, 11)); w((18, 7), (18, 11)); w((14, 11), (14, 17)); w((19, 11), (19, 17))
    # bays
    for k in range(5):
        u0 = 6 + 4.4 * k
        b.box(u0 + 1.7, 1.0, u0 + 2.7, 3.1); b.box(u0 + 3.3, 0.2, u0 + 3.9, 0.7); b.chair(u0 + 3.5, 2.2)
        if k < 4:
            b.box(u0 + 1.7, 20.9, u0 + 2.7, 23.0); b.box(u0 + 3.3, 23.3, u0 + 3.9, 23.8)
    # core / west block contents
    b.box(12.3, 10.2, 17.7, 10.8); b.chair(13.5, 9.6); b.chair(16.0, 9.6)
    b.box(8.4, 10.3, 11.8, 10.85)
    b.table(20.0, 8.5, 21.5, 9.5); b.box(23.5, 10.1, 25.6, 10.8)
    b.box(8.35, 11.2, 8.85, 16.5); b.box(13.3, 11.2, 13.85, 16.5)
    b.box(14.2, 11.2, 16.5, 11.8)
    b.desk(20.5, 11.25, 22.3, 12.1, "s"); b.chair(21.4, 12.6)
    b.box(0.2, 0.2, 2.5, 1.0); b.table(3.0, 2.5, 4.2, 3.5)
    b.box(0.3, 14.3, 2.4, 14.9)
    for u in (1.5, 2.5, 3.5, 4.5):
        b.chair(u, 9.4)
    b.box(0.2, 22.8, 5.8, 23.8); b.box(0.2, 16.3, 1.0, 21.0); b.box(3.0, 19.5, 4.2, 20.7)
    # west-leg squeeze
    b.box(6.1, 13.6, 6.75, 14.8); b.box(7.45, 13.8, 8.1, 14.5)
    b.passage(7.1, 14.15, 0.7, "corridor squeeze between linen trolley and crash cart", across=(1, 0))
    b.outside(14)
    b.space(17.0, 5.9, "hallway", "ring corridor around the core", group="ring", region=(6.5, 4.9, 27.5, 6.95))
    b.space(3.0, 11.5, "room", "waiting room", region=(0.1, 8.1, 5.9, 15.9))
    b.space(3.0, 5.5, "room", "relatives' room", region=(0.1, 1.1, 5.9, 7.9))
    b.space(3.0, 18.3, "room", "equipment store", region=(1.1, 16.1, 5.9, 22.7))
    for k in range(5):
        u0 = 6 + 4.4 * k
        b.space(u0 + 1.0, 3.6, "room", f"ICU bay S{k + 1}", region=(u0 + 0.1, 0.1, u0 + 4.3, 4.7))
        if k < 4:
            b.space(u0 + 1.0, 20.4, "room", f"ICU bay N{k + 1} (glass front barely mapped: grouped with the corridor)"
                    if k < 3 else "isolation room N4", group="ring" if k < 3 else None,
                    region=(u0 + 0.1, 19.3, u0 + 4.3, 23.9))
    b.space(15.0, 8.8, "room", "nurses' station", region=(12.1, 7.1, 17.9, 10.1))
    b.space(10.1, 8.6, "room", "medication room", region=(8.3, 7.1, 11.9, 10.2))
    b.space(22.0, 8.0, "room", "staff room", region=(18.1, 7.1, 25.7, 10.9))
    b.space(11.0, 13.8, "room", "supply store", region=(8.9, 11.1, 13.2, 16.9))
    b.space(16.5, 14.2, "room", "dirty utility", region=(14.1, 11.9, 18.9, 16.9))
    b.space(22.5, 14.5, "room", "doctors' office", region=(19.1, 12.2, 25.7, 16.9))
    b.route([(0.9, 12.0), (3.0, 12.0), (7.1, 12.0), (7.1, 6.0), (5.0, 6.0), (7.1, 6.0), (7.1, 5.9), (8.2, 5.9),
             (8.2, 4.2), (8.2, 5.9), (15.0, 5.9), (15.0, 8.7), (15.0, 5.9), (26.9, 5.9), (26.9, 9.0), (24.6, 9.0),
             (26.9, 9.0), (26.9, 18.1), (21.4, 18.1), (21.4, 20.4), (21.4, 18.1), (11.0, 18.1), (11.0, 15.0),
             (11.0, 18.1), (7.1, 18.1), (4.8, 18.0), (7.1, 18.1), (7.1, 12.0), (3.0, 12.0), (0.9, 12.0)])
    b.route([(0.9, 12.0), (7.1, 12.0), (7.1, 5.9), (26.9, 5.9), (26.9, 18.1), (16.5, 18.1), (16.5, 16.2),
             (16.5, 18.1), (7.1, 18.1), (7.1, 12.0), (3.0, 12.0)], bias=(0.06, -0.07, -0.5))
    return b


def factory():
    b = B("b5_factory", "Factory floor (40 x 26 m, axis-aligned): one big shop floor with a south row and a north row of "
          "machines (gaps of 0.8 / 0.7 / 0.75 m between machines = passages; a 1.5 m maintenance strip behind the "
          "south row), a solid conveyor line across the middle with a 0.9 m walk-through gap (passage), pallet "
          "racks in the east (0.9 m aisle = passage), a 3.5 m roller-door opening (not a door) and a personnel "
          "door to outside; rooms straight off the floor (no corridor): QC lab (1.4 m double door), tool crib behind "
          "a mesh front, locker room and WC behind 0.8 m doors, break room, office with a window, closed stair, "
          "compressor room. Return pass with a loop-closure error. Hard: machines look like small rooms, gaps "
          "between machines, rooms opening off a hall, mesh front.", (40, 26), theta=0, seed=17)
    w = b.wall
    X = EXT + 0.04
    w((0, 0), (30, 0), X); w((33.5, 0), (40, 0), X)          # 3.5 m roller-door opening u 30..33.5
    w((40, 0), (40, 26), X)
    w((40, 26), (0, 26), X)
    w((0, 26), (0, 0), X, doors=[(17.0, 1.0, "personnel door (shop floor to outside)", ("a", 1, 95))])
    w((0, 18), (8, 18), 0.15, doors=[(4.0, 1.4, "shop floor to QC lab (double door)", ("d", 1, 90))])
    w((8, 18), (13, 18), glass=True, mullion=1.0, doors=[(2.5, 1.0, "shop floor to tool crib (mesh front)",
                                                          ("a", 1, 90))])
    w((13, 18), (17.5, 18), 0.15, doors=[(1.0, 0.8, "shop floor to locker room", ("a", 1, 95))])
    w((17.5, 18), (20, 18), 0.15, doors=[(1.25, 0.8, "shop floor to WC", ("b", 1, 90))])
    w((20, 18), (27, 18), 0.15, doors=[(3.5, 1.0, "shop floor to break room", ("a", 1, 100))])
    w((27, 18), (33, 18), 0.15, doors=[(1.0, 0.9, "shop floor to office", ("a", 1, 90))], windows=[(2.0, 5.5)])
    w((33, 18), (36, 18), 0.15, doors=[{"at": 1.5, "w": 1.0, "note": "stair", "closed": True}])
    w((36, 18), (40, 18), 0.15, doors=[(2.0, 1.2, "shop floor to compressor room", ("b", 1, 95))])
    for u in (8, 13, 17.5, 20, 27, 33, 36):
        w((u, 18), (u, 26))
    # machines: south row (maintenance strip behind), north row
    for u0, u1 in [(2.0, 4.5), (5.3, 7.8), (9.4, 12.4), (13.1, 15.6), (17.6, 20.1), (21.3, 24.0), (25.5, 27.8)]:
        b.box(u0, 1.6, u1, 4.0)
    b.passage(4.9, 2.8, 0.8, "gap between two machines (south row)", across=(1, 0))
    b.passage(12.75, 2.8, 0.7, "gap between two machines (south row)", across=(1, 0))
    for u0, u1 in [(3.0, 6.0), (7.8, 10.5), (11.25, 14.0), (16.5, 19.0), (20.5, 23.0)]:
        b.box(u0, 13.5, u1, 16.0)
    b.passage(10.875, 14.75, 0.75, "gap between two machines (north row)", across=(1, 0))
    # conveyor with a walk-through gap at u 18
    b.box(6.0, 9.0, 17.55, 9.8); b.box(18.45, 9.0, 30.0, 9.8); b.box(30.0, 8.5, 32.0, 10.3)
    b.passage(18.0, 9.4, 0.9, "walk-through gap in the conveyor line", across=(1, 0))
    # racks east
    b.box(33.5, 2.0, 34.5, 15.0); b.box(35.7, 2.0, 36.7, 15.0); b.box(37.6, 2.0, 39.86, 15.0)
    b.passage(37.15, 8.5, 0.9, "aisle between pallet racks", across=(1, 0))
    # rooms
    b.box(0.2, 18.2, 0.8, 25.8); b.box(1.5, 25.2, 7.8, 25.8); b.box(3.0, 21.5, 5.5, 22.4)
    b.box(8.2, 25.2, 12.8, 25.8); b.box(12.2, 19.0, 12.8, 24.5)
    b.box(13.2, 20.0, 13.6, 25.8); b.box(16.9, 19.0, 17.3, 25.8); b.box(14.5, 22.0, 16.0, 22.4)
    b.box(17.7, 24.8, 18.4, 25.8)
    b.table(21.5, 21.0, 23.0, 22.0); b.table(24.0, 21.0, 25.5, 22.0)
    for p in [(21.2, 21.5), (23.3, 21.5), (23.7, 21.5), (25.8, 21.5)]:
        b.chair(*p)
    b.box(20.2, 25.2, 26.8, 25.8)
    b.desk(29.0, 24.8, 30.8, 25.7, "n"); b.chair(29.9, 24.3); b.box(32.3, 19.0, 32.85, 22.0)
    b.box(37.0, 22.0, 39.7, 25.7)
    b.outside(14)
    b.space(14.0, 7.0, "room", "shop floor", group="floor", region=(1.0, 4.2, 29.5, 13.3))
    b.space(32.5, 12.0, "room", "shop floor: rack zone", group="floor", region=(30.5, 10.5, 33.4, 17.9))
    b.space(4.0, 20.5, "room", "QC lab", region=(0.9, 18.1, 7.9, 25.1))
    b.space(10.5, 21.0, "room", "tool crib (mesh front barely mapped: grouped with the floor)", group="floor", region=(8.1, 18.1, 12.1, 25.1))
    b.space(15.25, 21.0, "room", "locker room", region=(13.7, 18.1, 16.8, 25.9))
    b.space(18.75, 21.5, "room", "WC", region=(17.6, 18.1, 19.9, 24.7))
    b.space(23.5, 23.5, "room", "break room", region=(20.1, 18.1, 26.9, 25.1))
    b.space(30.0, 21.5, "room", "office", region=(27.1, 18.1, 32.2, 24.2))
    b.space(38.0, 20.0, "room", "compressor room", region=(36.1, 18.1, 39.9, 21.9))
    b.route([(1.0, 9.0), (3.0, 7.0), (16.0, 7.0), (18.0, 8.2), (18.0, 10.6), (15.25, 12.0), (15.25, 17.0),
             (4.0, 17.0), (4.0, 19.6), (4.0, 17.0), (10.5, 17.0), (10.5, 19.6), (10.5, 17.0), (23.5, 17.0),
             (23.5, 20.0), (23.5, 17.0), (28.0, 17.0), (28.0, 19.4), (28.0, 17.0), (38.0, 17.0), (38.0, 19.5),
             (38.0, 17.0), (37.15, 16.0), (37.15, 1.0), (31.75, 0.9), (27.0, 0.85), (4.9, 0.85), (4.9, 4.6),
             (4.9, 6.0), (16.0, 6.0), (28.0, 6.5), (31.75, 2.5), (31.75, 0.4)])
    b.route([(31.75, 0.4), (31.75, 2.5), (32.75, 7.0), (32.75, 11.5), (6.0, 11.5), (3.0, 11.5), (3.0, 7.0), (1.0, 9.0)], bias=(0.12, 0.1, 0.5))
    return b


def _arc_door(b, cu, cv, r, deg, w, note, optional=False):
    import math
    a = math.radians(deg)
    b.doors.append({"center": (cu + r * math.cos(a), cv + r * math.sin(a)), "width_m": w, "optional": optional,
                    "note": note, "t": (-math.sin(a), math.cos(a)), "n": (math.cos(a), math.sin(a)), "glass": False})


def gallery():
    import math
    b = B("b5_gallery", "Small museum (L-shaped 30 x 26 m footprint, rotated 63 deg): entrance hall with ticket desk "
          "and a cloakroom (0.9 m door); a circular ROTUNDA gallery (r 5 m, curved wall, central plinth, benches) "
          "entered through a 1.8 m opening and left through a 1.6 m opening; gallery 2 with a free-standing "
          "display wall and cases (one room; a 0.82 m squeeze between the display wall and a case = passage); a 1.6 m double door into a CURVED corridor (quarter ring, 2.4 m wide) "
          "with doors in its curved walls: AV room inside the curve (1.0 m), store (0.9 m) and café (1.6 m) outside "
          "it; exit door at the corridor's end, terrace double door from the café. Return pass with loop-closure "
          "error. Hard: curved walls (no straight lines to fit), a round room, doors in curved walls, steep "
          "rotation, L footprint.", (30, 26), theta=63, seed=18)
    b.foot = [(0, 0), (30, 0), (30, 26), (18, 26), (18, 12), (0, 12)]
    w = b.wall
    w((0, 0), (30, 0), EXT)
    w((30, 0), (30, 26), EXT, doors=[(18.4, 1.2, "curved corridor end: exit door to outside", ("a", -1, 95))])
    w((30, 26), (18, 26), EXT, doors=[(6.0, 1.4, "café terrace double door to outside", ("d", -1, 90))])
    w((18, 26), (18, 12), EXT)
    w((18, 12), (0, 12), EXT)
    w((0, 12), (0, 0), EXT, doors=[(6.0, 1.8, "main entrance double door (entrance hall to outside)", ("d", 1, 90))])
    w((0, 9), (3, 9), doors=[(1.5, 0.9, "entrance hall to cloakroom", ("a", 1, 90))]); w((3, 9), (3, 12))
    w((8, 0), (8, 12), 0.2, doors=[(6.0, 1.8, "entrance hall to rotunda")])
    w((18, 0), (18, 12), 0.2, doors=[(6.0, 1.6, "rotunda to gallery 2")])
    # rotunda: circle centre (13, 6) r 5, openings at 180 deg (1.8 m) and 0 deg (1.6 m)
    hw = math.degrees(math.asin(0.9 / 5)); he = math.degrees(math.asin(0.8 / 5))
    b.arc(13, 6, 5, he, 180 - hw, 0.2); b.arc(13, 6, 5, 180 + hw, 360 - he, 0.2)
    b.rbox(13, 6, 1.2, 1.2, 45); b.rbox(13, 3.0, 1.6, 0.45, 0); b.rbox(13, 9.0, 1.6, 0.45, 0)
    # gallery 2
    w((18, 12), (30, 12), 0.15, doors=[(5.6, 1.6, "gallery 2 to curved corridor (double door)", ("d", 1, 90))])
    b.seg((22, 3.5), (22, 8.5), 0.15)
    b.box(24.5, 2.0, 25.5, 3.0); b.box(24.5, 9.0, 25.5, 10.0); b.box(27.5, 5.5, 29.5, 6.5)
    b.box(22.9, 5.0, 23.9, 6.0)          # display case beside the free-standing wall
    b.passage(22.49, 5.5, 0.82, "squeeze between the free-standing display wall and a display case", across=(1, 0))
    # curved corridor: centre (30, 12), inner r 5.2, outer r 7.6, from 90 to 180 deg
    C = (30, 12)
    ha = math.degrees(math.asin(0.5 / 5.2))
    b.arc(*C, 5.2, 90, 135 - ha, 0.15); b.arc(*C, 5.2, 135 + ha, 180, 0.15)
    _arc_door(b, *C, 5.2, 135, 1.0, "curved corridor to AV room (door in the curved wall)")
    hc = math.degrees(math.asin(0.8 / 7.6)); hs = math.degrees(math.asin(0.45 / 7.6))
    b.arc(*C, 7.6, 90, 115 - hc, 0.15); b.arc(*C, 7.6, 115 + hc, 165 - hs, 0.15); b.arc(*C, 7.6, 165 + hs, 180, 0.15)
    _arc_door(b, *C, 7.6, 115, 1.6, "curved corridor to café (opening in the curved wall)")
    _arc_door(b, *C, 7.6, 165, 0.9, "curved corridor to store (door in the curved wall)")
    x17 = 30 - math.sqrt(7.6 ** 2 - 5 ** 2)
    b.seg((18, 17), (x17, 17), 0.12)
    # contents
    b.box(5.5, 8.0, 7.6, 8.7); b.box(0.2, 0.5, 0.6, 3.0)                    # ticket desk, bench
    b.box(0.2, 11.2, 2.8, 11.8)                                               # coat rail
    b.box(18.2, 12.2, 18.8, 16.7); b.box(19.5, 16.2, 21.5, 16.8)             # store shelves
    for k in range(3):
        a = math.radians(110 + 15 * k)
        b.chair(30 + 2.6 * math.cos(a), 12 + 2.6 * math.sin(a))
    b.box(29.3, 12.2, 29.85, 14.5)                                            # AV screen cabinet
    b.box(18.2, 23.5, 18.8, 25.8)                                             # café counter
    for u0, v0 in [(20.5, 21.0), (23.0, 22.5), (20.5, 24.0), (26.5, 23.2)]:
        b.table(u0, v0, u0 + 0.8, v0 + 0.8); b.chair(u0 - 0.3, v0 + 0.4); b.chair(u0 + 1.1, v0 + 0.4)
    b.outside(14)
    b.space(4.0, 5.0, "room", "entrance hall", region=(0.7, 0.2, 7.8, 7.8))
    b.space(1.5, 10.5, "room", "cloakroom", region=(0.1, 9.1, 2.9, 11.1))
    b.space(13.0, 8.0, "room", "rotunda gallery", region=(10.0, 3.6, 16.0, 8.6))
    b.space(20.0, 9.5, "room", "gallery 2", region=(18.2, 0.2, 29.8, 11.8))
    def polar(r, deg):
        a = math.radians(deg)
        return (30 + r * math.cos(a), 12 + r * math.sin(a))
    b.space(*polar(6.4, 150), "hallway", "curved corridor")
    b.space(*polar(3.0, 135), "room", "AV room (inside the curve)", region=(26.5, 12.3, 29.2, 15.5))
    b.space(19.8, 14.5, "room", "store", region=(18.9, 12.1, 21.5, 16.0))
    b.space(21.5, 20.5, "room", "café", region=(19.0, 19.5, 29.9, 25.9))
    arc_pts = [polar(6.4, d) for d in range(175, 89, -10)]
    b.route([(1.0, 6.0), (4.0, 6.0), (1.5, 7.8), (1.5, 10.2), (1.5, 7.8), (4.0, 6.0), (9.5, 6.0), (10.5, 8.0),
             (15.5, 8.0), (17.0, 6.0), (19.2, 6.0), (20.0, 2.5), (22.49, 2.5), (22.49, 7.5), (23.6, 10.5), (23.6, 12.8)] + arc_pts[:1] +
            [polar(6.4, 165), polar(8.6, 165), polar(6.4, 165)] + arc_pts[2:5] +
            [polar(6.4, 135), polar(4.0, 135), polar(6.4, 135)] + arc_pts[5:6] +
            [polar(6.4, 115), polar(8.8, 115), (24.0, 21.5), polar(8.8, 115), polar(6.4, 115)] + arc_pts[7:] +
            [(29.6, 18.4)])
    b.route([(29.6, 18.4)] + arc_pts[::-1] + [(23.6, 12.8), (23.6, 10.5), (26.8, 11.0), (26.8, 7.8), (26.5, 4.2),
             (26.5, 1.1), (20.0, 1.1), (19.2, 6.0), (17.0, 6.0), (15.5, 4.0), (10.5, 4.0), (9.5, 6.0), (4.0, 6.0), (1.0, 6.0)],
            bias=(0.06, 0.07, 0.6))
    return b


BUILDINGS = [sports, hotel, library, garage, mall, icu, factory, gallery]
