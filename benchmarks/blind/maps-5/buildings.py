"""The blind6 buildings (building frame: u east, v north, metres). See README.md."""
import math

from sim import B

EXT = 0.24


def dormitory():
    b = B("b6_dormitory", "Student dormitory floor (36 x 13 m, rotated 17 deg): entrance lobby (1.6 m double entrance "
          "door, mailboxes) with a warden's office, a 2.0 m opening into an open-plan common room (sofas, kitchenette, "
          "dining table), a 1.6 m double door onto a 1.8 m corridor lined with small study bedrooms (3 x 5.5 m, "
          "0.85 m doors, three closed, most only seen through their doors); a WIDE JUNCTION where a 3.5 m cross "
          "corridor leaves the corridor south to an exit door (corridor + cross corridor = one hallway); a shared "
          "bathroom (1.0 m door, shower stalls), a laundry (1.0 m door) whose washer row and folding island leave a "
          "0.78 m aisle leading to the drying room door (0.8 m). Return pass with a loop-closure error. Hard: many "
          "tiny rooms seen only through doors, wide junction, narrow laundry aisle.", (36, 13), theta=17, seed=21)
    w = b.wall
    w((0, 0), (36, 0), EXT, doors=[(2.5, 1.6, "entrance double door (lobby to outside)", ("d", -1, 90)),
                                  (21.75, 1.2, "south exit door (cross corridor to outside)", ("a", -1, 95))])
    w((36, 0), (36, 13), EXT)
    w((36, 13), (0, 13), EXT)
    w((0, 13), (0, 0), EXT)
    w((0, 4), (8, 4), doors=[(2.5, 2.0, "lobby to common room (2.0 m opening)")])
    w((5, 0), (5, 4), doors=[(2.6, 0.9, "lobby to warden's office", ("b", -1, 90))])
    w((8, 0), (8, 13), doors=[(6.4, 1.6, "common room to corridor (double door)", ("d", 1, 90))])
    # south corridor wall with the south bedrooms (u 8..20), the laundry (u 23.5..31)
    sd = []
    for k in range(4):
        if k == 1:
            sd.append({"at": 3 * k + 0.8, "w": 0.85, "note": "bedroom S2", "closed": True})
        else:
            sd.append((3 * k + 0.8, 0.85, f"corridor to bedroom S{k + 1}", ("a", -1, 80 + 5 * k)))
    w((8, 5.5), (20, 5.5), doors=sd)
    for u in (11, 14, 17):
        w((u, 0), (u, 5.5))
    w((20, 0), (20, 5.5)); w((23.5, 0), (23.5, 5.5))          # cross corridor u 20..23.5
    w((23.5, 5.5), (36, 5.5), doors=[(2.0, 1.0, "corridor to laundry", ("b", -1, 90))])
    w((31, 0), (31, 5.5), doors=[(1.125, 0.8, "laundry to drying room", ("a", -1, 90))])
    # north corridor wall with the north bedrooms (u 8..29) and the bathroom (u 29..36)
    nd = []
    for k in range(7):
        if k in (2, 5):
            nd.append({"at": 3 * k + 0.8, "w": 0.85, "note": f"bedroom N{k + 1}", "closed": True})
        else:
            nd.append((3 * k + 0.8, 0.85, f"corridor to bedroom N{k + 1}", ("a", 1, 78 + 4 * k)))
    nd.append((22.2, 1.0, "corridor to shared bathroom", ("a", 1, 90)))
    w((8, 7.3), (36, 7.3), doors=nd)
    for u in (11, 14, 17, 20, 23, 26, 29):
        w((u, 7.3), (u, 13))
    # bedrooms
    for k in range(4):
        u0 = 8 + 3 * k
        b.box(u0 + 0.12, 0.12, u0 + 1.02, 2.12); b.box(u0 + 2.3, 0.12, u0 + 2.94, 1.4)
        b.box(u0 + 2.3, 4.3, u0 + 2.94, 5.44); b.chair(u0 + 2.0, 0.9)
    for k in range(7):
        u0 = 8 + 3 * k
        b.box(u0 + 0.12, 10.9, u0 + 1.02, 12.88); b.box(u0 + 2.3, 11.6, u0 + 2.94, 12.88)
        b.box(u0 + 2.3, 7.36, u0 + 2.94, 8.4); b.chair(u0 + 2.0, 12.0)
    # bathroom: shower stall partitions + basins
    for u in (31.0, 32.5, 34.0):
        b.seg((u, 11.5), (u, 12.94), 0.06)
    b.box(29.06, 8.5, 29.6, 11.0)
    # laundry: washers along the south wall, folding island -> 0.78 m aisle to the drying room door
    b.box(23.7, 0.12, 30.6, 0.72); b.box(24.6, 1.5, 30.2, 2.5); b.box(23.6, 4.6, 24.4, 5.44)
    b.passage(27.4, 1.11, 0.78, "laundry: aisle between washer row and folding island (to the drying room)",
              across=(0, 1))
    b.table(32.0, 3.6, 35.5, 4.3)                     # drying racks
    b.box(20.06, 3.0, 20.8, 4.0)                      # vending machine in the cross corridor
    # common room / lobby / office
    b.box(0.12, 12.3, 4.5, 12.88); b.box(4.6, 12.2, 5.3, 12.88)
    b.box(1.0, 7.0, 3.0, 7.8); b.box(0.12, 8.2, 0.9, 10.2); b.table(1.4, 8.4, 2.6, 9.4)
    b.table(4.5, 9.5, 6.5, 10.7)
    for p in [(4.9, 9.2), (6.1, 9.2), (4.9, 11.0), (6.1, 11.0)]:
        b.chair(*p, ang=10)
    b.box(5.5, 4.06, 7.5, 4.5); b.box(7.5, 10.0, 7.94, 12.5)
    b.box(0.12, 0.8, 0.5, 3.2)                        # mailboxes
    b.box(6.5, 0.12, 7.94, 0.8); b.box(7.4, 2.5, 7.94, 3.94)
    b.outside(14)
    b.space(3.0, 2.0, "room", "entrance lobby", region=(0.6, 0.2, 4.9, 3.9))
    b.space(6.6, 2.0, "room", "warden's office", region=(5.1, 0.9, 7.9, 3.9))
    b.space(4.5, 7.5, "room", "common room (lounge + kitchenette)", region=(0.2, 4.2, 7.8, 12.2))
    b.space(15.0, 6.4, "hallway", "bedroom corridor with the wide junction", region=(8.5, 5.6, 35.5, 7.2))
    for k in range(4):
        if k == 1:
            continue
        u0 = 8 + 3 * k
        b.space(u0 + 1.7, 3.0, "room", f"bedroom S{k + 1}", region=(u0 + 0.1, 2.2, u0 + 2.9, 5.4))
    for k in range(7):
        if k in (2, 5):
            continue
        u0 = 8 + 3 * k
        b.space(u0 + 1.7, 9.8, "room", f"bedroom N{k + 1}", region=(u0 + 0.1, 7.4, u0 + 2.9, 10.8))
    b.space(33.0, 9.5, "room", "shared bathroom", region=(29.7, 7.4, 35.9, 11.4))
    b.space(27.5, 3.8, "room", "laundry", region=(23.6, 2.6, 30.9, 5.4))
    b.space(33.5, 2.2, "room", "drying room", region=(31.1, 0.2, 35.9, 5.4))
    b.route([(2.5, 0.8), (2.5, 2.2), (4.3, 2.6), (6.3, 2.6), (4.3, 2.6), (2.5, 2.6), (2.5, 5.0), (4.0, 6.0),
             (4.0, 8.6), (3.5, 11.7), (1.4, 11.7), (3.5, 11.7), (7.0, 11.7), (7.0, 9.6), (7.0, 6.4), (8.8, 6.4),
             (8.8, 4.5), (9.7, 3.0), (8.8, 4.5), (8.8, 6.4), (8.8, 8.5), (9.7, 9.5), (8.8, 8.5), (8.8, 6.4),
             (21.75, 6.4), (21.75, 1.0), (21.75, 6.4), (25.5, 6.4), (25.5, 4.5), (24.1, 3.2), (24.1, 1.11),
             (30.55, 1.11), (31.6, 1.11), (33.5, 2.5), (31.6, 1.11), (30.55, 1.11), (30.6, 3.5), (25.5, 3.5),
             (25.5, 6.4), (30.2, 6.4), (30.2, 8.5), (33.0, 9.5), (30.2, 8.5), (30.2, 6.4), (35.3, 6.4)])
    b.route([(35.3, 6.4), (17.8, 6.4), (17.8, 8.6), (17.8, 6.4), (14.8, 6.4), (14.8, 4.3), (14.8, 6.4), (7.0, 6.4),
             (2.5, 5.0), (2.5, 1.0)], bias=(0.06, -0.05, 0.5))
    return b


def station():
    b = B("b6_station", "Small train station (40 x 24 m, rotated -28 deg): a 28 x 16 m concourse behind a glass front "
          "(two 1.8 m glass double doors) with pillars, a kiosk, benches and ticket machines, separated from the "
          "platform access hall by a TICKET-GATE LINE (three 0.6 m gate lanes = narrow passages, a 0.9 m accessible "
          "lane, a glass barrier, solid wall stubs; concourse + platform hall grouped); two 1.8 m double doors to the "
          "platform stairs; north rooms: ticket office (solid front with a sales window, 1.0 m door), waiting room "
          "(1.6 m double door, bench rows), men's / women's WCs (0.9 m), café (2.0 m opening), left-luggage room "
          "(1.2 m) and staff room (0.9 m) off the platform hall. Return pass with a loop-closure error. Hard: gate "
          "lanes close together, glass front fans, huge open concourse with clutter.", (40, 24), theta=-28, seed=22)
    w = b.wall
    w((0, 0), (6, 0), EXT)
    w((6, 0), (22, 0), glass=True, doors=[(4.0, 1.8, "west entrance (glass double door) to outside", ("d", -1, 90)),
                                          (12.0, 1.8, "east entrance (glass double door) to outside", ("d", -1, 90))])
    w((22, 0), (40, 0), EXT)
    w((40, 0), (40, 24), EXT, doors=[(4.0, 1.8, "platform hall to platform 1 stairs (double door)", ("d", -1, 90)),
                                    (11.0, 1.8, "platform hall to platform 2 stairs (double door)", ("d", -1, 90))])
    w((40, 24), (0, 24), EXT)
    w((0, 24), (0, 0), EXT, doors=[(14.0, 1.2, "west side door (concourse to outside)", ("a", -1, 95))])
    w((0, 16), (6, 16), windows=[(0.5, 3.3)], doors=[(4.5, 1.0, "concourse to ticket office", ("a", 1, 90))])
    w((6, 16), (28, 16), doors=[(3.5, 1.6, "concourse to waiting room (double door)", ("d", 1, 90)),
                               (8.5, 0.9, "concourse to men's WC", ("a", 1, 90)),
                               (11.5, 0.9, "concourse to women's WC", ("b", 1, 90)),
                               (17.5, 2.0, "concourse to café (2.0 m opening)")])
    w((28, 16), (40, 16), doors=[(2.5, 1.2, "platform hall to left-luggage room", ("a", 1, 90)),
                                (8.0, 0.9, "platform hall to station staff room", ("b", 1, 95))])
    for u in (6, 13, 16, 19, 28, 33):
        w((u, 16), (u, 24))
    # ticket-gate line at u 28: wall stub, gate cabinets, glass barrier, wall stub
    w((28, 0), (28, 4)); w((28, 12), (28, 16))
    for v0 in (4.0, 4.9, 5.8, 6.7, 7.9):
        b.box(27.2, v0, 28.8, v0 + 0.3)
    b.seg((28, 8.2), (28, 12), 0.03, kind=2)
    for v in (9.4, 10.6, 11.8):
        b.box(27.96, v - 0.04, 28.04, v + 0.04)
    for i, v in enumerate((4.6, 5.5, 6.4)):
        b.passage(28.0, v, 0.6, f"ticket gate lane {i + 1} (concourse to platform hall)", across=(0, 1))
    b.passage(28.0, 7.45, 0.9, "accessible wide gate lane (0.9 m)", across=(0, 1), optional=True)
    # concourse contents
    b.box(0.12, 3.0, 0.7, 4.2); b.box(0.12, 5.0, 0.7, 6.2)            # ticket machines
    for cu, cv in [(9, 6), (9, 11), (20, 6), (20, 11), (16.0, 8.25)]:
        b.box(cu - 0.3, cv - 0.3, cu + 0.3, cv + 0.3)                  # pillars
    b.box(13.0, 7.5, 15.0, 9.0)                                         # kiosk
    b.passage(15.35, 8.25, 0.7, "squeeze between the kiosk and a pillar", across=(1, 0), optional=True)
    b.box(10.5, 3.0, 13.0, 3.5); b.box(15.5, 3.0, 18.0, 3.5); b.box(22.0, 10.0, 24.5, 10.5)   # benches
    b.box(25.0, 15.4, 27.5, 15.94)                                      # departure board stand
    # platform hall
    b.box(37.0, 13.0, 39.88, 15.88)                                     # lift / stair core
    b.box(30.5, 2.5, 33.0, 3.0); b.box(39.3, 6.5, 39.88, 8.5)
    # rooms north
    b.box(0.12, 16.1, 3.5, 16.7); b.box(0.12, 21.0, 0.7, 23.88); b.box(2.0, 23.3, 5.94, 23.88)
    b.box(7.0, 18.5, 12.0, 19.0); b.box(7.0, 20.5, 12.0, 21.0)
    b.box(13.06, 22.0, 15.94, 23.88); b.box(15.4, 17.0, 15.94, 20.0)
    b.box(16.06, 22.0, 18.94, 23.88); b.box(18.4, 17.0, 18.94, 20.0)
    b.box(26.8, 16.5, 27.94, 23.0)                                      # café counter
    for u0, v0 in [(20.0, 20.5), (20.0, 22.5), (24.2, 21.5)]:
        b.table(u0, v0, u0 + 0.8, v0 + 0.8); b.chair(u0 - 0.3, v0 + 0.4); b.chair(u0 + 1.1, v0 + 0.4)
    b.box(28.1, 17.5, 28.7, 23.88); b.box(29.5, 23.3, 32.9, 23.88); b.box(32.3, 17.5, 32.94, 22.0)
    b.table(35.0, 20.0, 37.0, 21.2); b.box(39.3, 17.0, 39.88, 23.0)
    b.outside(14)
    b.space(14.0, 5.5, "room", "concourse", group="concourse", region=(1.0, 1.0, 27.0, 15.0))
    b.space(34.0, 8.0, "room", "platform access hall (beyond the ticket gates)", group="concourse",
            region=(29.0, 1.0, 39.5, 15.0))
    b.space(2.5, 20.0, "room", "ticket office", region=(0.8, 16.8, 5.9, 23.2))
    b.space(9.5, 22.2, "room", "waiting room", region=(6.1, 21.1, 12.9, 23.9))
    b.space(14.5, 19.3, "room", "men's WC", region=(13.1, 16.1, 15.3, 21.9))
    b.space(17.5, 19.3, "room", "women's WC", region=(16.1, 16.1, 18.3, 21.9))
    b.space(22.5, 18.5, "room", "café", region=(19.1, 16.1, 26.7, 23.9))
    b.space(30.5, 20.0, "room", "left-luggage room", region=(28.8, 16.1, 32.2, 23.2))
    b.space(36.5, 18.3, "room", "station staff room", region=(33.1, 16.1, 39.2, 23.9))
    b.route([(10.0, 0.9), (10.0, 2.2), (2.0, 2.2), (2.0, 14.0), (4.5, 14.0), (4.5, 17.5), (4.5, 14.5), (9.5, 14.5),
             (9.5, 17.7), (12.5, 17.7), (12.5, 22.0), (7.5, 22.0), (12.5, 22.0), (12.5, 17.7), (9.5, 17.7),
             (9.5, 14.5), (23.5, 14.5), (23.5, 19.0), (23.5, 14.5), (26.5, 12.5), (26.5, 7.45), (29.5, 7.45),
             (34.0, 7.45), (38.5, 4.0), (38.5, 11.0), (39.3, 11.0), (34.0, 14.5), (30.5, 14.5), (30.5, 18.5),
             (30.5, 14.5), (36.0, 14.5)][:-1] +
            [(35.5, 12.0), (36.0, 14.5), (36.0, 18.5), (36.0, 14.5), (35.5, 12.0), (30.0, 10.0), (29.5, 5.5),
             (26.5, 5.5), (24.0, 2.0), (15.0, 2.0), (10.0, 1.0)])
    b.route([(10.0, 1.0), (10.0, 13.0), (20.0, 13.0), (26.0, 13.0), (27.0, 6.4), (29.5, 6.4), (34.0, 6.4),
             (34.0, 2.0), (29.5, 2.0)], bias=(-0.07, 0.05, -0.5))
    return b


def dental():
    b = B("b6_dental", "Dental practice (24 x 15 m, axis-aligned): waiting room (1.2 m entrance door, benches, toy "
          "box) with a triangular reception office behind an ANGLED 45-degree wall (0.8 m door and a glass counter "
          "window in the diagonal), hygienist room (0.9 m); a 1.4 m opening into an L/T-shaped 1.6 m corridor: three "
          "treatment rooms (1.0 m doors, dental chairs), X-ray room (1.2 m lead door), sterilisation room split by "
          "two bench runs with a 0.8 m gap (passage; the two zones are grouped), treatment room 4, staff WC, closed "
          "store, office, staff room with a kitchen peninsula leaving a 0.69 m squeeze to the kitchenette (passage; "
          "grouped); fire exit east, staff entrance north. Return pass with a loop-closure error. Hard: angled "
          "wall with a door in it, small rooms, squeezes that look like doors.", (24, 15), theta=0, seed=23)
    w = b.wall
    w((0, 0), (24, 0), EXT, doors=[(3.0, 1.2, "entrance door (waiting room to outside)", ("a", -1, 95))])
    w((24, 0), (24, 15), EXT, doors=[(7.3, 1.0, "corridor east end: fire exit to outside", ("a", -1, 95))])
    w((24, 15), (0, 15), EXT, doors=[(9.2, 1.0, "north corridor end: staff entrance to outside", ("a", -1, 90))])
    w((0, 15), (0, 0), EXT)
    d = math.hypot(4.5, 4.5)
    w((0, 4.5), (4.5, 9), windows=[(4.3, 5.7)],
      doors=[(d / 2, 0.8, "waiting room to reception office (door in the angled wall)", ("b", 1, 165))])
    w((0, 9), (9, 9), doors=[(6.0, 0.9, "waiting room to hygienist room", ("a", 1, 90))])
    w((9, 0), (9, 15), doors=[(7.3, 1.4, "waiting room to corridor (1.4 m opening)")])
    w((9, 6.5), (24, 6.5), doors=[(1.0, 1.0, "corridor to treatment room 1", ("a", -1, 90)),
                                 (5.0, 1.0, "corridor to treatment room 2", ("a", -1, 90)),
                                 (9.0, 1.0, "corridor to treatment room 3", ("a", -1, 90)),
                                 (13.5, 1.2, "corridor to X-ray room (lead door)", ("a", -1, 90))])
    w((13, 0), (13, 6.5)); w((17, 0), (17, 6.5)); w((21, 0), (21, 6.5), 0.2)
    w((9, 8.1), (14, 8.1), doors=[(1.2, 0.9, "corridor to sterilisation room", ("a", 1, 90))])
    w((15.6, 8.1), (24, 8.1), doors=[(2.2, 1.0, "corridor to treatment room 4", ("b", 1, 90)),
                                    (5.9, 0.8, "corridor to staff WC", ("a", 1, 90)),
                                    {"at": 7.6, "w": 0.8, "note": "store", "closed": True}])
    w((14, 8.1), (14, 15), doors=[(5.4, 0.9, "corridor to office", ("a", 1, 90))])
    w((15.6, 8.1), (15.6, 15), doors=[(5.4, 0.9, "corridor to staff room", ("b", -1, 90))])
    w((9, 12), (14, 12)); w((15.6, 12), (24, 12)); w((20.5, 8.1), (20.5, 12)); w((22.5, 8.1), (22.5, 12))
    # treatment rooms
    for u0 in (9, 13, 17):
        b.rbox(u0 + 2.0, 3.0, 0.7, 1.9, 15); b.box(u0 + 0.3, 0.12, u0 + 3.7, 0.7)
        b.box(u0 + 3.35, 2.5, u0 + 3.94, 4.5)
    b.box(23.3, 1.0, 23.88, 2.5); b.box(22.0, 2.0, 23.0, 3.0)                 # X-ray
    b.rbox(18.6, 10.4, 0.7, 1.9, 90); b.box(16.0, 11.3, 20.0, 11.94)          # treatment room 4
    b.box(21.2, 11.3, 21.8, 11.94); b.box(22.0, 9.0, 22.44, 9.6)              # WC
    # sterilisation room: two bench runs with a 0.8 m gap
    b.box(11.3, 8.16, 11.8, 9.55); b.box(11.3, 10.35, 11.8, 11.94)
    b.box(13.2, 8.3, 13.94, 9.5); b.box(12.0, 11.4, 13.94, 11.94); b.box(9.06, 11.3, 10.8, 11.94)
    b.passage(11.55, 9.95, 0.8, "sterilisation room: gap between the two bench runs (dirty to clean zone)",
              across=(0, 1))
    # office, staff room
    b.box(9.3, 14.2, 11.0, 14.94); b.box(9.06, 12.5, 9.6, 13.8)
    b.box(19.8, 12.75, 20.4, 14.94)
    b.passage(20.1, 12.405, 0.69, "staff room: squeeze between kitchen peninsula and wall (to the kitchenette)",
              across=(0, 1))
    b.box(23.3, 12.6, 23.94, 14.94); b.box(21.0, 14.3, 21.7, 14.94)
    b.table(17.0, 13.6, 18.4, 14.5)
    # hygienist room, reception, waiting room
    b.rbox(4.5, 12.0, 0.7, 1.9, 80); b.box(0.12, 14.3, 3.5, 14.94); b.box(8.3, 10.0, 8.94, 12.0)
    b.box(0.12, 8.4, 0.6, 8.94)
    b.box(4.0, 0.12, 8.7, 0.6); b.box(8.4, 1.0, 8.94, 5.5); b.box(7.0, 8.4, 8.5, 8.94); b.table(4.0, 3.5, 5.2, 4.3)
    b.outside(12)
    b.space(5.0, 5.8, "room", "waiting room", region=(1.0, 0.8, 8.3, 8.8))
    b.space(1.3, 7.7, "room", "reception office (triangle behind the angled wall)", region=(0.15, 6.6, 2.2, 8.9))
    b.space(6.8, 13.0, "room", "hygienist room", region=(0.2, 9.2, 8.2, 14.2))
    b.space(18.0, 7.3, "hallway", "L/T corridor", region=(9.5, 6.6, 23.5, 8.0))
    for i, u0 in enumerate((9, 13, 17)):
        b.space(u0 + 2.3, 5.2, "room", f"treatment room {i + 1}", region=(u0 + 0.2, 4.2, u0 + 3.8, 6.3))
    b.space(22.5, 4.6, "room", "X-ray room", region=(21.2, 3.2, 23.8, 6.3))
    b.space(10.2, 10.0, "room", "sterilisation room: dirty zone", group="sterilisation", region=(9.1, 8.2, 11.2, 11.2))
    b.space(12.6, 10.3, "room", "sterilisation room: clean zone", group="sterilisation", region=(11.9, 9.6, 13.9, 11.3))
    b.space(16.6, 9.5, "room", "treatment room 4", region=(15.7, 8.2, 20.4, 11.2))
    b.space(21.5, 10.2, "room", "staff WC", region=(20.6, 8.2, 22.4, 11.2))
    b.space(11.8, 13.3, "room", "office", region=(9.7, 12.1, 13.9, 14.1))
    b.space(17.0, 12.9, "room", "staff room", group="staff", region=(15.7, 12.1, 19.7, 14.9))
    b.space(22.2, 13.4, "room", "staff room: kitchenette behind the peninsula", group="staff",
            region=(20.5, 12.1, 23.2, 14.2))
    b.route([(3.0, 0.8), (3.0, 2.5), (6.5, 2.5), (6.5, 6.0), (2.67, 6.33), (1.76, 7.24), (1.3, 7.7), (1.76, 7.24), (2.67, 6.33), (6.0, 7.0),
             (6.0, 8.5), (6.0, 10.3), (6.8, 12.0), (6.0, 10.3), (2.0, 10.3), (6.0, 10.3), (6.0, 8.0), (8.0, 7.3),
             (10.2, 7.3), (10.2, 9.95), (12.6, 9.95), (12.6, 10.8), (12.6, 9.95), (10.2, 9.95), (10.2, 7.3),
             (10.0, 7.3), (10.0, 5.5), (11.5, 5.0), (10.0, 5.5), (10.0, 7.3), (14.8, 7.3), (14.8, 13.5),
             (13.0, 13.5), (11.0, 13.5), (14.8, 13.5), (16.0, 13.5), (18.5, 12.9), (19.3, 12.405), (21.2, 12.405),
             (22.0, 13.4), (21.2, 12.405), (19.3, 12.405), (16.0, 13.3), (14.8, 13.3), (14.8, 14.2), (14.8, 7.3),
             (17.8, 7.3), (17.8, 9.2), (16.6, 9.5), (17.8, 9.2), (17.8, 7.3), (18.0, 7.3), (18.0, 5.4), (18.0, 7.3),
             (21.5, 7.3), (22.5, 7.3), (22.5, 4.5), (22.5, 7.3), (23.3, 7.3)])
    b.route([(23.3, 7.3), (14.0, 7.3), (14.0, 5.4), (14.0, 7.3), (9.5, 7.3), (6.5, 6.0), (6.5, 2.5), (3.0, 2.5), (3.0, 0.8)],
            bias=(0.05, 0.06, 0.45))
    return b


def courthouse():
    b = B("b6_courthouse", "County courthouse floor (34 x 24 m + a curved apse, rotated 41 deg): entrance vestibule "
          "(1.8 m double door) and lobby split by a SECURITY SCREENING line (fence, baggage X-ray, walk-through "
          "metal-detector arch = 0.75 m passage, 0.94 m staff gate; vestibule + lobby grouped); a 2.0 m opening into "
          "a 3.5 m main corridor with a WIDE T-JUNCTION to a 2.4 m cross corridor (one hallway); courtroom 1 with a "
          "CURVED apse wall behind the judge's bench, public bench rows, and a bar rail whose 0.8 m gate is a "
          "passage (public gallery + well grouped), entered through a 1.8 m double door; judge's chambers off the "
          "courtroom; clerk's office, jury lobby (1.2 m) and jury room (0.9 m); hearing room (1.6 m double door), "
          "two consultation rooms, robing room / library, witness waiting room (1.2 m), toilets (0.8 m), registry "
          "office with a counter (two grouped points), staff room; exit door north. Return pass with a "
          "loop-closure error. Hard: curved wall, rail and screening line that look like walls with doors, wide "
          "corridor junction.", (34, 24), theta=41, seed=24)
    C, R = (17.0, 11.25), 13.25
    a0 = math.degrees(math.atan2(-11.25, -7.0)) % 360
    a1 = math.degrees(math.atan2(-11.25, 7.0)) % 360
    apse = [(C[0] + R * math.cos(math.radians(a0 + (a1 - a0) * i / 16)),
             C[1] + R * math.sin(math.radians(a0 + (a1 - a0) * i / 16))) for i in range(17)]
    b.foot = [(0, 0)] + apse + [(34, 0), (34, 24), (0, 24)]
    w = b.wall
    w((0, 0), (10, 0), EXT, doors=[(5.0, 1.8, "main entrance double door (vestibule to outside)", ("d", -1, 90))])
    b.arc(C[0], C[1], R, a0, a1, th=EXT, n=16)
    w((24, 0), (34, 0), EXT)
    w((34, 0), (34, 24), EXT)
    w((34, 24), (0, 24), EXT, doors=[(16.8, 1.0, "cross corridor north end: exit door", ("a", -1, 90))])
    w((0, 24), (0, 0), EXT)
    w((10, 0), (10, 10))
    w((0, 10), (34, 10), doors=[(5.0, 2.0, "lobby to main corridor (2.0 m opening)"),
                               (17.0, 1.8, "main corridor to courtroom 1 (double door)", ("d", -1, 90)),
                               (26.5, 0.9, "main corridor to clerk's office", ("a", -1, 90)),
                               (31.5, 1.2, "main corridor to jury lobby", ("b", -1, 90))])
    w((24, 0), (24, 10), doors=[(3.0, 0.9, "courtroom 1 to judge's chambers", ("a", -1, 90))])
    w((24, 6), (34, 6), doors=[(7.5, 0.9, "jury lobby to jury room", ("b", -1, 90))])
    w((29, 0), (29, 10))
    w((0, 13.5), (16, 13.5), doors=[(4.5, 1.6, "main corridor to hearing room (double door)", ("d", 1, 90)),
                                   (10.75, 0.9, "main corridor to consultation room 1", ("a", 1, 90)),
                                   (14.25, 0.9, "main corridor to consultation room 2", ("b", 1, 90))])
    w((18.4, 13.5), (34, 13.5), doors=[(3.3, 1.2, "main corridor to witness waiting room", ("a", 1, 90)),
                                      (8.1, 0.8, "main corridor to toilets", ("b", 1, 90)),
                                      (12.6, 1.0, "main corridor to registry office", ("a", 1, 95))])
    w((16, 13.5), (16, 24), doors=[(7.5, 1.0, "cross corridor to robing room / library", ("a", 1, 90))])
    w((18.4, 13.5), (18.4, 24), doors=[(8.0, 0.9, "cross corridor to staff room", ("b", -1, 90))])
    w((9, 13.5), (9, 24)); w((12.5, 13.5), (12.5, 18.5)); w((9, 18.5), (16, 18.5))
    w((25, 13.5), (25, 19)); w((28, 13.5), (28, 24)); w((18.4, 19), (28, 19))
    # security screening line across the lobby at v 3.5
    b.seg((0.06, 3.5), (3.2, 3.5), 0.06); b.box(3.2, 3.0, 4.6, 4.0); b.seg((4.6, 3.5), (5.0, 3.5), 0.06)
    b.box(5.0, 3.1, 5.12, 3.9); b.box(5.87, 3.1, 5.99, 3.9)
    b.seg((5.99, 3.5), (8.0, 3.5), 0.06); b.seg((9.0, 3.5), (9.94, 3.5), 0.06)
    b.passage(5.495, 3.5, 0.75, "walk-through metal-detector arch (vestibule to lobby)", across=(1, 0))
    b.passage(8.5, 3.5, 0.94, "staff side gate in the screening fence", across=(1, 0), optional=True)
    b.box(0.12, 5.5, 0.6, 8.5); b.box(7.8, 8.2, 9.3, 8.9)
    # courtroom 1
    for vk in (5.6, 6.8, 8.0):
        b.box(11.2, vk, 16.1, vk + 0.45); b.box(17.9, vk, 22.8, vk + 0.45)
    b.seg((10.06, 4.6), (16.56, 4.6), 0.08); b.seg((17.44, 4.6), (23.94, 4.6), 0.08)
    b.passage(17.0, 4.6, 0.8, "gate in the courtroom bar rail (public gallery to the well)", across=(1, 0))
    b.desk(12.0, 2.6, 14.5, 3.4, "n"); b.desk(19.5, 2.6, 22.0, 3.4, "n")
    b.box(15.5, 1.6, 18.5, 2.1); b.box(14.5, -0.6, 19.5, 0.5); b.box(20.5, 0.3, 21.6, 1.4)
    # chambers, clerk, jury
    b.box(26.5, 4.8, 28.5, 5.94); b.box(28.3, 0.5, 28.94, 3.5)
    b.box(24.1, 6.1, 25.5, 7.0); b.box(28.3, 6.5, 28.94, 9.5)
    b.box(29.1, 9.0, 29.6, 9.94)
    b.table(30.0, 2.0, 33.0, 3.5)
    for u in (30.5, 31.5, 32.5):
        b.chair(u, 1.6); b.chair(u, 3.9)
    # corridor clutter
    b.box(0.5, 12.95, 3.2, 13.44); b.box(15.2, 10.1, 15.7, 10.6); b.box(19.0, 10.06, 21.0, 10.5)
    b.box(27.5, 10.06, 28.7, 10.5); b.box(6.5, 12.95, 8.5, 13.44)
    # north rooms
    b.box(2.0, 22.8, 7.0, 23.6); b.table(1.5, 19.0, 3.5, 19.8); b.table(5.5, 19.0, 7.5, 19.8)
    b.box(1.0, 15.5, 3.8, 15.9); b.box(5.2, 15.5, 8.0, 15.9)
    b.table(9.6, 17.4, 11.9, 18.2); b.table(13.1, 17.4, 15.4, 18.2)
    b.box(9.3, 23.3, 15.7, 23.94); b.box(9.06, 19.0, 9.7, 23.0); b.table(11.5, 20.5, 13.5, 21.5)
    b.box(24.3, 14.5, 24.94, 18.5); b.table(20.0, 16.0, 21.2, 16.8)
    b.box(25.06, 17.5, 27.94, 18.94)
    b.box(28.06, 16.5, 32.5, 17.1); b.box(33.3, 19.0, 33.94, 23.5); b.box(28.5, 23.3, 32.5, 23.94)
    b.table(21.0, 21.0, 23.0, 22.0); b.box(27.3, 19.5, 27.94, 23.5)
    b.outside(14)
    b.space(2.0, 1.7, "room", "entrance vestibule (before the screening line)", group="lobby",
            region=(0.3, 0.3, 9.7, 3.2))
    b.space(5.0, 7.0, "room", "lobby (after the screening line)", group="lobby", region=(0.8, 4.0, 9.7, 9.7))
    b.space(12.0, 11.75, "hallway", "main corridor + cross corridor (wide T junction)", region=(0.5, 10.2, 33.5, 13.3))
    b.space(17.0, 7.0, "room", "courtroom 1: public gallery", group="courtroom", region=(10.2, 4.8, 23.8, 9.9))
    b.space(12.3, 1.0, "room", "courtroom 1: well (judge's bench, counsel tables)", group="courtroom",
            region=(10.2, -1.5, 23.8, 4.4))
    b.space(26.5, 2.5, "room", "judge's chambers", region=(24.2, 0.2, 28.2, 4.7))
    b.space(27.0, 8.0, "room", "clerk's office", region=(25.6, 6.2, 28.2, 9.9))
    b.space(30.5, 8.0, "room", "jury lobby", region=(29.7, 6.2, 33.9, 9.9))
    b.space(29.9, 4.9, "room", "jury room", region=(29.1, 0.2, 33.9, 5.9))
    b.space(4.5, 17.3, "room", "hearing room", region=(0.2, 16.0, 8.9, 22.7))
    b.space(10.75, 15.8, "room", "consultation room 1", region=(9.1, 13.6, 12.4, 17.3))
    b.space(14.25, 15.8, "room", "consultation room 2", region=(12.6, 13.6, 15.9, 17.3))
    b.space(12.5, 19.5, "room", "robing room / library", region=(9.8, 18.6, 15.9, 23.2))
    b.space(21.7, 17.8, "room", "witness waiting room", region=(18.5, 13.6, 24.2, 18.9))
    b.space(26.5, 15.3, "room", "toilets", region=(25.1, 13.6, 27.9, 17.4))
    b.space(30.5, 15.0, "room", "registry office: public side of the counter", group="registry",
            region=(28.1, 13.6, 33.9, 16.4))
    b.space(30.5, 20.3, "room", "registry office: staff side", group="registry", region=(28.1, 17.2, 33.2, 23.2))
    b.space(24.5, 21.5, "room", "staff room", region=(18.5, 19.1, 27.2, 23.9))
    b.route([(5.0, 0.8), (5.495, 2.5), (5.495, 4.5), (5.0, 6.5), (2.5, 8.5), (5.0, 9.0), (5.0, 11.75),
             (4.5, 11.75), (4.5, 17.5), (2.0, 17.5), (7.0, 17.5), (4.5, 17.5), (4.5, 11.75), (10.75, 11.75),
             (10.75, 15.3), (10.75, 11.75), (17.0, 11.75), (17.0, 9.5), (17.0, 5.3), (17.0, 4.0), (11.2, 4.0),
             (11.2, 0.3), (11.2, 4.0), (19.0, 4.0), (23.0, 4.0), (23.0, 3.0), (25.5, 3.0), (26.5, 2.0), (25.5, 3.0),
             (23.0, 3.0), (23.0, 4.0), (17.0, 4.0), (17.0, 9.5), (17.0, 11.75), (17.2, 11.75), (17.2, 21.0),
             (15.0, 21.0), (12.5, 19.5), (15.0, 21.0), (17.2, 21.0), (17.2, 21.3), (19.8, 21.3), (20.0, 20.0), (24.5, 20.0), (20.0, 20.0),
             (19.8, 21.3), (17.2, 21.3), (17.2, 23.3), (17.2, 11.75), (21.7, 11.75), (21.7, 16.0), (21.7, 11.75),
             (26.5, 11.75), (26.5, 8.5), (26.5, 11.75), (31.0, 11.75), (31.0, 15.5), (33.2, 15.5), (33.2, 17.6), (31.0, 20.0),
             (33.2, 17.6), (33.2, 15.5), (31.0, 15.5), (31.0, 11.75), (31.5, 11.75), (31.5, 7.5), (31.5, 5.3), (30.0, 4.9),
             (31.5, 5.3), (31.5, 7.5), (31.5, 11.75), (33.0, 11.75)])
    b.route([(33.0, 11.75), (5.0, 11.75), (5.0, 9.0), (8.5, 6.0), (8.5, 2.0), (5.0, 0.8)], bias=(0.08, -0.06, 0.55))
    return b


def vet():
    b = B("b6_vet_clinic", "Veterinary clinic (26 x 16 m, rotated 6 deg): waiting room split into a dog side and a "
          "cat side by a partial partition (two grouped points), 1.0 m entrance door, reception counter, scale; "
          "staff room (0.9 m) and dispensary (0.8 m, shelving island with a 0.8 m aisle = passage) off the waiting "
          "room; a 1.0 m door into a 1.5 m back corridor with three consult rooms (0.9 m doors; consult 1 also "
          "opens to the waiting room), X-ray (1.2 m), surgery (1.2 m double door) with a prep room behind it, a "
          "kennel ward (1.6 m double door) with cage banks whose 0.8 m aisle is a passage; yard door east. Return "
          "pass with a loop-closure error. Hard: partition alcove, kennel islands, rooms with two doors.",
          (26, 16), theta=6, seed=25)
    w = b.wall
    w((0, 0), (26, 0), EXT, doors=[(3.0, 1.0, "entrance door (waiting room to outside)", ("a", -1, 95))])
    w((26, 0), (26, 16), EXT, doors=[(6.75, 1.0, "back corridor east end: door to the yard", ("a", -1, 90))])
    w((26, 16), (0, 16), EXT)
    w((0, 16), (0, 0), EXT)
    b.seg((5, 0.12), (5, 4.5), 0.1)                                     # dog / cat partition
    w((10, 0), (10, 16), doors=[(3.0, 0.9, "waiting room to consult room 1", ("b", -1, 90)),
                               (6.75, 1.0, "waiting room to back corridor", ("a", -1, 90))])
    w((0, 9), (10, 9), doors=[(2.5, 0.9, "waiting room to staff room", ("a", 1, 90)),
                             (7.5, 0.8, "waiting room to dispensary", ("b", 1, 90))])
    w((5, 9), (5, 16))
    w((10, 6), (26, 6), doors=[(2.0, 0.9, "corridor to consult room 1", ("a", -1, 90)),
                              (6.0, 0.9, "corridor to consult room 2", ("a", -1, 90)),
                              (10.0, 0.9, "corridor to consult room 3", ("a", -1, 90)),
                              (14.0, 1.2, "corridor to X-ray room", ("b", -1, 90))])
    for u in (14, 18, 22):
        w((u, 0), (u, 6))
    w((10, 7.5), (26, 7.5), doors=[(3.0, 1.2, "corridor to surgery (double door)", ("d", 1, 90)),
                                  (8.0, 1.6, "corridor to kennel ward (double door)", ("d", 1, 90))])
    w((16, 7.5), (16, 16), doors=[(6.7, 0.9, "kennel ward to prep room", ("a", 1, 90))])
    w((10, 12.5), (16, 12.5), doors=[(1.5, 0.9, "surgery to prep room", ("a", 1, 90))])
    # waiting room
    b.box(0.12, 1.0, 0.6, 6.0); b.box(5.5, 0.12, 9.5, 0.6); b.box(5.05, 5.5, 7.0, 6.1); b.box(0.2, 7.4, 1.0, 8.2)
    b.box(8.6, 7.6, 9.94, 8.94)
    # consult rooms, X-ray
    for u0 in (10, 14, 18):
        b.box(u0 + 1.4, 1.8, u0 + 2.6, 2.5); b.box(u0 + 3.36, 1.0, u0 + 3.94, 3.5)
    b.box(23.0, 1.5, 25.0, 3.0)
    # surgery, prep
    b.box(12.5, 9.5, 13.5, 10.5); b.box(14.5, 9.0, 15.2, 9.7); b.box(10.06, 8.0, 10.7, 12.0)
    b.box(12.5, 13.6, 13.5, 14.4); b.box(10.3, 15.3, 15.7, 15.94)
    # kennel ward
    b.box(16.06, 15.2, 25.94, 15.94); b.box(25.3, 8.0, 25.94, 14.5)
    b.box(17.5, 10.0, 24.0, 10.9); b.box(17.5, 11.7, 24.0, 12.6)
    b.passage(20.75, 11.3, 0.8, "kennel ward: aisle between two cage banks", across=(0, 1))
    # staff room, dispensary
    b.table(1.5, 12.0, 3.5, 13.0); b.box(0.12, 15.3, 3.0, 15.94); b.box(4.2, 13.0, 4.94, 15.0)
    b.box(5.06, 10.0, 5.6, 15.94); b.box(9.4, 10.0, 9.94, 15.94); b.box(6.7, 11.0, 8.6, 14.5)
    b.passage(9.0, 12.75, 0.8, "dispensary: aisle between shelving island and wall shelves", across=(1, 0))
    b.outside(12)
    b.space(2.5, 3.0, "room", "waiting room: dog side", group="waiting", region=(0.7, 0.7, 4.9, 8.8))
    b.space(7.5, 3.0, "room", "waiting room: cat side", group="waiting", region=(5.2, 0.7, 9.8, 5.4))
    b.space(2.5, 10.8, "room", "staff room", region=(0.2, 9.1, 4.9, 11.9))
    b.space(6.6, 10.3, "room", "dispensary", region=(5.7, 9.1, 9.3, 10.9))
    b.space(17.0, 6.75, "hallway", "back corridor", region=(10.5, 6.1, 25.5, 7.4))
    for i, u0 in enumerate((10, 14, 18)):
        b.space(u0 + 2.0, 4.2, "room", f"consult room {i + 1}", region=(u0 + 0.2, 2.6, u0 + 3.2, 5.0))
    b.space(24.0, 4.5, "room", "X-ray room", region=(22.2, 3.1, 25.8, 5.2))
    b.space(14.0, 11.5, "room", "surgery", region=(10.8, 7.6, 15.9, 12.4))
    b.space(11.8, 14.6, "room", "prep room", region=(10.2, 12.6, 15.9, 15.2))
    b.space(20.5, 8.8, "room", "kennel ward", region=(16.2, 7.6, 25.2, 9.9))
    b.route([(3.0, 0.8), (3.0, 4.9), (7.5, 4.9), (7.5, 2.5), (7.5, 4.9), (9.0, 3.0), (11.0, 3.0), (12.0, 4.2),
             (12.0, 6.75), (13.0, 6.75), (13.0, 8.5), (14.0, 8.6), (14.0, 11.3), (11.5, 11.8), (11.5, 14.9),
             (15.0, 14.9), (15.0, 14.2), (17.0, 14.2), (24.5, 14.0), (24.6, 11.3), (17.0, 11.3), (16.75, 9.0),
             (18.0, 8.6), (18.0, 6.75), (16.0, 6.75), (16.0, 5.0), (16.0, 6.75), (24.0, 6.75), (24.0, 4.5),
             (24.0, 6.75), (25.3, 6.75)])
    b.route([(25.3, 6.75), (10.5, 6.75), (8.8, 6.75), (7.5, 8.2), (7.5, 10.4), (9.0, 10.6), (9.0, 15.0),
             (6.2, 15.0), (6.2, 10.6), (7.5, 10.4), (7.5, 8.2), (2.5, 8.3), (2.5, 10.8), (2.5, 8.3), (3.0, 4.9),
             (3.0, 0.8)], bias=(-0.05, 0.07, -0.45))
    return b


def cinema():
    b = B("b6_cinema", "Three-screen cinema (36 x 26 m, rotated -52 deg): an open-plan FOYER behind a glass front (two "
          "1.8 m glass double doors) with an L concession counter, queue posts, pillars, sofas, bistro tables and "
          "arcade machines; a ticket booth (0.9 m door, sales window); a 2.0 m opening to a 2.5 m screen corridor "
          "(one hallway) with three screens behind 1.8 m double doors (stepped seating rows; only screen 2 driven, "
          "screens 1 and 3 seen only through their doors), men's / women's toilets and a staff office (0.9 m); a "
          "stock room (1.0 m staff door from the foyer) with racking: a 0.85 m aisle (passage) and a 1.0 m aisle "
          "(optional); fire exit at the corridor's east end. Return pass with a loop-closure error. Hard: huge "
          "cluttered foyer, seating rows, partly unexplored screens, racking aisles.", (36, 26), theta=-52, seed=26)
    w = b.wall
    w((0, 0), (4, 0), EXT)
    w((4, 0), (18, 0), glass=True, doors=[(4.0, 1.8, "west glass double door (foyer to outside)", ("d", -1, 90)),
                                          (10.0, 1.8, "east glass double door (foyer to outside)", ("d", -1, 90))])
    w((18, 0), (36, 0), EXT)
    w((36, 0), (36, 26), EXT, doors=[(13.25, 1.0, "screen corridor east end: fire exit", ("a", -1, 90))])
    w((36, 26), (0, 26), EXT)
    w((0, 26), (0, 0), EXT)
    w((4, 0), (4, 4), doors=[(2.5, 0.9, "foyer to ticket booth", ("b", 1, 90))])
    w((0, 4), (4, 4), windows=[(0.5, 3.5)])
    w((0, 12), (36, 12), doors=[(11.0, 2.0, "foyer to screen corridor (2.0 m opening)"),
                               (24.0, 0.9, "corridor to men's toilets", ("a", -1, 90)),
                               (28.0, 0.9, "corridor to women's toilets", ("b", -1, 90)),
                               (33.0, 0.9, "corridor to staff office", ("a", -1, 90))])
    w((22, 0), (22, 12), doors=[(3.0, 1.0, "foyer to stock room (staff door)", ("a", -1, 90))])
    w((22, 6), (36, 6)); w((26, 6), (26, 12)); w((30, 6), (30, 12))
    w((0, 14.5), (36, 14.5), doors=[(1.6, 1.8, "corridor to screen 1 (double door)", ("d", 1, 90)),
                                   (13.6, 1.8, "corridor to screen 2 (double door)", ("d", 1, 90)),
                                   (25.6, 1.8, "corridor to screen 3 (double door)", ("d", 1, 90))])
    w((12, 14.5), (12, 26), 0.2); w((24, 14.5), (24, 26), 0.2)
    for u0 in (0, 12, 24):
        for k in range(7):
            vk = 16.5 + k
            b.box(u0 + 3.2, vk, u0 + 11.95, vk + 0.5)
    # foyer
    b.box(14.0, 9.5, 20.0, 10.3); b.box(19.2, 6.0, 20.0, 9.5); b.box(15.0, 11.3, 17.0, 11.94)
    for k in range(6):
        b.dot(10.0 + 0.7 * k, 7.5, 0.04)
    b.box(1.0, 8.0, 3.0, 8.8); b.box(1.0, 10.8, 3.0, 11.6); b.table(1.2, 9.2, 2.6, 10.2)
    b.box(5.0, 11.2, 6.0, 11.94); b.box(6.2, 11.2, 7.2, 11.94)
    b.box(8.7, 3.7, 9.3, 4.3); b.box(14.7, 3.7, 15.3, 4.3)
    for u0, v0 in [(5.6, 5.6), (8.0, 8.2)]:
        b.table(u0, v0, u0 + 0.8, v0 + 0.8); b.chair(u0 - 0.35, v0 + 0.4); b.chair(u0 + 1.15, v0 + 0.4)
    b.rbox(20.8, 2.0, 0.8, 0.1, 30)                     # poster stand
    b.box(0.12, 3.3, 3.5, 3.88)                          # booth desk under the window
    # stock room racking
    b.box(23.0, 0.12, 35.5, 0.75); b.box(24.0, 1.6, 34.0, 2.25); b.box(24.0, 3.25, 34.0, 3.9)
    b.passage(29.0, 1.175, 0.85, "stock room: aisle between two racks", across=(0, 1))
    b.passage(29.0, 2.75, 1.0, "stock room: 1.0 m aisle between two racks", across=(0, 1), optional=True)
    # toilets, office
    b.box(22.06, 9.5, 22.6, 11.4); b.box(24.6, 6.06, 25.94, 7.6); b.box(26.06, 6.06, 27.4, 7.6)
    b.box(29.4, 9.5, 29.94, 11.4)
    b.desk(34.0, 6.2, 35.8, 7.2, "s"); b.box(30.2, 6.06, 31.0, 8.0)
    b.outside(14)
    b.space(10.0, 5.5, "room", "foyer", region=(4.5, 4.5, 21.5, 11.5))
    b.space(2.0, 1.8, "room", "ticket booth", region=(0.2, 0.2, 3.9, 3.2))
    b.space(18.0, 13.25, "hallway", "screen corridor", region=(0.5, 12.2, 35.5, 14.3))
    for i, u0 in enumerate((0, 12, 24)):
        b.space(u0 + 6.0, 24.3, "room", f"screen {i + 1}", region=(u0 + 0.2, 15.0, u0 + 11.8, 25.8))
    b.space(24.0, 8.8, "room", "men's toilets", region=(22.7, 7.7, 25.9, 11.9))
    b.space(28.0, 8.8, "room", "women's toilets", region=(26.1, 7.7, 29.3, 11.9))
    b.space(33.0, 9.5, "room", "staff office", region=(31.1, 7.4, 35.9, 11.9))
    b.space(29.0, 4.9, "room", "stock room", region=(22.2, 3.95, 35.8, 5.9))
    b.route([(8.0, 0.8), (8.0, 2.5), (5.0, 2.5), (2.0, 2.0), (5.0, 2.5), (5.0, 4.8), (3.5, 5.2), (3.5, 9.8), (8.0, 10.5),
             (11.0, 10.5), (11.0, 13.25), (1.6, 13.25), (1.6, 15.5), (1.6, 13.25), (13.6, 13.25), (13.6, 24.0),
             (20.0, 24.2), (13.6, 24.0), (13.6, 13.25), (24.0, 13.25), (24.0, 10.8), (24.0, 13.25), (25.6, 13.25),
             (25.6, 15.3), (25.6, 13.25), (33.0, 13.25), (33.0, 9.0), (33.0, 13.25), (35.3, 13.25)])
    b.route([(35.3, 13.25), (11.0, 13.25), (11.0, 10.5), (18.0, 5.0), (21.0, 3.0), (23.2, 3.0), (23.4, 4.9),
             (34.9, 4.9), (34.9, 1.175), (23.4, 1.175), (23.4, 3.0), (21.0, 3.0), (15.0, 2.0), (14.0, 0.8)],
            bias=(0.07, 0.06, -0.5))
    return b


BUILDINGS = [dormitory, station, dental, courthouse, vet, cinema]
