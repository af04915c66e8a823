"""The blind7 buildings (building frame: u east, v north, metres). See README.md."""
import math

from sim import B

EXT = 0.24


def kchair(b, u, v):
    """A child's chair: four legs 0.28 m apart."""
    for x, y in [(-0.14, -0.14), (0.14, -0.14), (0.14, 0.14), (-0.14, 0.14)]:
        b.dot(u + x, v + y, 0.018)


def kindergarten():
    b = B("b7_kindergarten", "Kindergarten (24 x 16 m, rotated -33 deg, 0.025 m cells): an entrance hall / cloakroom "
          "(wall cubbies and a cubby island with a 0.8 m slot between them, 1.2 m entrance door) behind a glass partition with a 1.6 m glass double door onto a 2 m corridor; "
          "staff office (doors from the hall and the corridor), kitchen, group room 'Ladybirds' with a nap room "
          "behind a 0.8 m door (nap room seen only through that door; its corridor door is closed); north: group "
          "room 'Bumblebees' (garden door), a children's washroom between the two north group rooms (doors to both "
          "and to the corridor), group room 'Owls' with a play loft that leaves a 0.7 m slot along a shelf, and a "
          "play hall (1.8 m double door, climbing frame, ball pit, glass garden facade with a glass double door). "
          "Children walking during mapping. Hard: fine cells, small furniture everywhere, glass.",
          (24, 16), theta=-33, seed=31, margin=8.0, res=0.025)
    w = b.wall
    w((0, 0), (24, 0), EXT, doors=[(3.0, 1.2, "entrance door (entrance hall to outside)", ("a", 1, 95))],
      windows=[(14.2, 18.4)])
    w((24, 0), (24, 8), EXT)
    w((24, 8), (24, 16), glass=True, doors=[(4.0, 1.6, "play hall glass double door to the garden", ("d", -1, 90))])
    w((24, 16), (0, 16), EXT, doors=[(20.5, 1.0, "Bumblebees garden door (to outside)", ("b", -1, 85))],
      windows=[(8.5, 12.5)])
    w((0, 16), (0, 0), EXT)
    # south band: entrance hall u0..6, office 6..9.5, kitchen 9.5..13, Ladybirds 13..19.5, nap room 19.5..24
    w((6, 0), (6, 6), doors=[(3.0, 0.9, "entrance hall to staff office", ("a", -1, 90))])
    w((0, 6), (6, 6), glass=True, doors=[(3.0, 1.6, "entrance hall to corridor (glass double door)", ("d", 1, 90))])
    w((6, 6), (24, 6), doors=[(1.75, 0.9, "corridor to staff office", ("b", -1, 90)),
                              (5.25, 0.9, "corridor to kitchen", ("a", -1, 90)),
                              (9.0, 1.0, "corridor to Ladybirds group room", ("a", -1, 95)),
                              {"at": 15.5, "w": 0.9, "note": "nap room corridor door", "closed": True}])
    w((9.5, 0), (9.5, 6)); w((13, 0), (13, 6))
    w((19.5, 0), (19.5, 6), doors=[(3.5, 0.8, "Ladybirds to nap room", ("a", -1, 85))])
    # north band: Bumblebees 0..7, washroom 7..10, Owls 10..17, play hall 17..24
    w((0, 8), (24, 8), doors=[(3.5, 1.0, "corridor to Bumblebees group room", ("a", 1, 90)),
                              (8.5, 0.9, "corridor to children's washroom", ("b", 1, 90)),
                              (13.5, 1.0, "corridor to Owls group room", ("a", 1, 100)),
                              (20.5, 1.8, "corridor to play hall (double door)", ("d", 1, 90))])
    w((7, 8), (7, 16), doors=[(4.5, 0.8, "Bumblebees to washroom", ("a", -1, 90))])
    w((10, 8), (10, 16), doors=[(2.0, 0.8, "washroom to Owls", ("b", 1, 90))])
    w((17, 8), (17, 16), doors=[(6.0, 1.2, "Owls to play hall", ("b", -1, 90))])
    # entrance hall: cubbies, bench, pram corner
    b.box(0.12, 0.8, 0.55, 5.4); b.box(4.2, 0.8, 5.7, 1.2); b.box(4.6, 4.2, 5.88, 5.5)
    b.box(1.35, 2.0, 1.75, 4.6)                      # double-sided cubby island
    b.passage(0.95, 3.3, 0.8, "cloakroom: slot between the wall cubbies and the cubby island", across=(1, 0))
    b.clutter((0, 0.12), (6, 0.12), 1, 0, avoid=[(2.2, 3.8)])
    # office
    b.desk(6.2, 0.2, 7.8, 0.9, "s"); b.desk(8.6, 1.2, 9.4, 2.8, "e"); b.chair(7.0, 1.4); b.chair(8.1, 2.0)
    b.box(8.3, 4.6, 9.44, 5.4)
    # kitchen
    b.box(9.56, 0.12, 12.94, 0.75); b.box(12.3, 0.75, 12.94, 4.0); b.table(10.2, 2.3, 11.6, 3.3)
    b.box(9.56, 4.2, 10.2, 5.94)
    # Ladybirds
    for (u0, v0) in [(14.0, 1.2), (16.6, 1.2), (14.8, 3.6)]:
        b.table(u0, v0, u0 + 1.4, v0 + 0.8)
        for du in (0.35, 1.05):
            kchair(b, u0 + du, v0 - 0.3); kchair(b, u0 + du, v0 + 1.1)
    b.box(13.06, 3.5, 13.5, 5.94); b.box(18.0, 4.9, 19.44, 5.4)
    # nap room cots
    for k in range(3):
        for m in range(2):
            b.box(20.2 + 1.3 * k, 0.4 + 3.9 * m, 20.9 + 1.3 * k, 1.7 + 3.9 * m)
    # Bumblebees
    b.table(1.5, 10.0, 3.0, 11.0); b.table(4.2, 12.6, 5.6, 13.6)
    for p in [(1.8, 9.7), (2.6, 9.7), (1.8, 11.3), (2.6, 11.3), (4.5, 12.3), (5.3, 12.3), (4.5, 13.9), (5.3, 13.9)]:
        kchair(b, *p)
    b.box(0.12, 9.0, 0.5, 12.0); b.box(5.8, 14.8, 6.94, 15.88); b.seg((0.12, 13.8), (2.2, 13.8), 0.06)
    # washroom: cubicle partitions, basins
    b.seg((8.0, 15.88), (8.0, 14.5), 0.05); b.seg((9.0, 15.88), (9.0, 14.5), 0.05)
    b.box(7.06, 8.9, 7.5, 11.5)
    # Owls: play loft + shelf -> 0.7 m slot
    b.box(11.5, 12.0, 13.5, 14.5); b.box(10.06, 11.6, 10.8, 15.2)
    b.passage(11.15, 13.25, 0.7, "Owls: slot between the shelf and the play loft", across=(1, 0))
    b.table(13.6, 9.3, 15.1, 10.3); b.table(14.6, 11.6, 16.1, 12.6)
    for p in [(13.9, 9.0), (14.7, 9.0), (14.9, 12.9), (15.7, 12.9)]:
        kchair(b, *p)
    b.box(16.4, 14.5, 16.94, 15.88)
    # play hall: climbing frame posts, slide, ball pit, mats
    for p in [(18.8, 12.6), (20.4, 12.6), (20.4, 14.2), (18.8, 14.2)]:
        b.dot(*p, 0.05)
    b.rbox(21.2, 13.0, 1.6, 0.45, -30)
    b.box(22.0, 14.2, 23.88, 15.88); b.box(22.5, 8.12, 23.88, 9.0)
    b.outside(12, dmin=1.5, dmax=6.0)
    # people (children / staff) while mapping
    b.person([(18.0, 10.0), (23.0, 11.0), (22.0, 10.0)], speed=0.25)
    b.person([(19.5, 15.3)], start=0, stop=700)
    b.person([(15.5, 14.2)], start=300, stop=1400)
    b.person([(1.5, 7.0), (15.0, 7.0)], speed=0.3, start=200, stop=900)
    # spaces
    b.space(2.5, 2.8, "room", "entrance hall / cloakroom", region=(0.7, 0.3, 5.8, 5.8))
    b.space(7.6, 3.4, "room", "staff office", region=(6.2, 1.0, 9.3, 5.8))
    b.space(11.0, 4.6, "room", "kitchen", region=(9.6, 1.0, 12.2, 5.8))
    b.space(16.2, 3.0, "room", "group room Ladybirds", region=(13.6, 0.3, 19.3, 5.8))
    b.space(21.8, 3.3, "room", "nap room", region=(19.7, 0.3, 23.8, 5.8))
    b.space(12.0, 7.0, "hallway", "corridor", region=(0.5, 6.2, 23.5, 7.8))
    b.space(3.5, 12.0, "room", "group room Bumblebees", region=(0.6, 8.2, 6.8, 15.8))
    b.space(8.5, 12.0, "room", "children's washroom", region=(7.6, 8.2, 9.9, 14.3))
    b.space(15.0, 14.0, "room", "group room Owls", region=(10.9, 8.2, 16.8, 15.8))
    b.space(19.5, 10.5, "room", "play hall", region=(17.2, 8.2, 23.8, 15.8))
    b.route([(3.0, 1.6), (2.0, 1.6), (0.95, 1.7), (0.95, 5.0), (2.2, 5.3), (3.0, 3.0), (4.8, 3.0), (7.2, 3.0), (7.6, 4.0), (7.2, 3.0), (4.8, 3.0), (3.0, 3.0),
             (3.0, 7.0), (1.0, 7.0), (3.5, 7.0), (3.5, 9.2), (3.6, 12.0), (3.5, 14.8), (3.6, 12.0), (6.3, 11.6),
             (6.3, 12.5), (8.5, 12.5), (8.5, 10.0), (10.9, 10.0), (12.6, 11.2), (16.5, 11.0), (16.5, 13.6),
             (15.0, 15.2), (13.9, 15.2), (16.5, 14.0), (17.8, 14.0), (19.5, 15.2), (21.0, 15.3), (21.6, 14.0),
             (23.2, 12.8), (23.2, 10.8), (21.0, 10.8), (20.5, 9.6), (20.5, 7.0), (15.0, 7.0), (15.0, 5.2),
             (17.0, 5.0), (17.0, 2.8), (19.0, 2.8), (19.0, 3.5), (17.0, 3.0), (17.0, 5.0), (15.0, 5.2),
             (15.0, 7.0), (11.25, 7.0),
             (11.25, 5.0), (11.0, 3.8), (11.25, 5.0), (11.25, 7.0), (23.4, 7.0)])
    b.route([(23.4, 7.0), (13.5, 7.0), (13.5, 8.8), (12.0, 10.6), (11.15, 11.0), (11.15, 15.5), (12.0, 15.5),
             (13.9, 15.2), (16.5, 14.0), (17.8, 14.0), (17.8, 9.6), (20.5, 9.6), (20.5, 7.0), (7.75, 7.0),
             (7.75, 4.0), (7.5, 3.0), (4.8, 3.0), (3.0, 3.0), (3.0, 1.6)], bias=(0.05, -0.04, 0.45))
    return b




def fire_station():
    b = B("b7_fire_station", "Fire station (40 x 26 m, axis-aligned, 0.1 m cells): an apparatus bay (22 x 18 m) with "
          "three fire engines and a utility van parked, closed roller doors between piers, gear lockers along the west "
          "wall leaving a 0.85 m squeeze beside engine 1, hose rack, workbench, a personnel door; an L-shaped corridor "
          "(north + east legs, one hallway) with a 1.6 m double door and a 1.0 m door from the bay, two more bay doors "
          "from the east leg; north: bunk room (seen only through its door), locker room (a locker island leaves a "
          "0.9 m aisle along the wall lockers), fitness room "
          "(treadmills, racks; a second door from the corridor's east leg); east: watch room, office, kitchen + mess "
          "and a day room joined by a 2.6 m arch (grouped). Return pass with a loop-closure error. Hard: coarse "
          "cells, huge bay with vehicles, arch.", (40, 26), theta=0, seed=32, res=0.1)
    w = b.wall
    w((0, 0), (24, 0), EXT, doors=[(22.8, 1.0, "bay personnel door (to outside)", ("b", -1, 90))])
    w((24, 0), (40, 0), EXT, doors=[(1.0, 1.2, "main entrance (east corridor to outside)", ("a", 1, 90))])
    w((40, 0), (40, 26), EXT)
    w((40, 26), (0, 26), EXT, doors=[(36.0, 1.0, "bunk room fire escape (to outside)", ("a", -1, 80))],
      windows=[(2.0, 5.0), (8.0, 12.0)])
    w((0, 26), (0, 0), EXT)
    for u in (6.0, 12.0, 18.0):                     # piers between the closed roller doors
        b.box(u - 0.3, 0.12, u + 0.3, 0.55)
    w((0, 18), (24, 18), doors=[(6.0, 1.6, "apparatus bay to north corridor (double door)", ("d", -1, 90)),
                                (19.0, 1.0, "apparatus bay to north corridor (single door)", ("a", 1, 90))])
    w((24, 0), (24, 18), doors=[(4.0, 1.2, "apparatus bay to east corridor (turnout door)", ("a", 1, 90)),
                                (12.0, 1.0, "apparatus bay to east corridor (north)", ("b", 1, 90))])
    w((0, 20), (24, 20), doors=[(4.0, 0.9, "corridor to bunk room", ("a", 1, 85)),
                                (11.0, 0.9, "corridor to locker / shower room", ("b", 1, 90)),
                                (16.0, 1.2, "corridor to fitness room", ("a", 1, 90))])
    w((8, 20), (8, 26)); w((14, 20), (14, 26))
    w((24, 20), (24, 26), doors=[(3.0, 0.9, "east corridor to fitness room (side door)", ("a", 1, 90))])
    w((26, 0), (26, 26), doors=[(2.5, 0.9, "corridor to watch room", ("a", -1, 90)),
                                (7.0, 0.9, "corridor to office", ("b", -1, 90)),
                                (12.0, 1.2, "corridor to kitchen / mess", ("a", -1, 95)),
                                (22.0, 0.9, "corridor to day room", ("b", -1, 90))])
    w((26, 5), (40, 5)); w((26, 9), (40, 9))
    w((26, 17), (40, 17), doors=[{"at": 7.0, "w": 2.6, "note": "2.6 m arch between mess and day room (optional)",
                                  "optional": True}])
    # bay: engines, van, lockers, hose rack, workbench, compressor, clutter
    b.box(1.55, 3.0, 4.15, 12.5); b.box(8.0, 3.0, 10.6, 12.5); b.box(14.2, 2.5, 16.8, 11.5); b.box(19.6, 3.0, 21.6, 8.5)
    b.box(0.12, 2.0, 0.7, 16.5)
    b.passage(1.125, 8.0, 0.85, "bay: squeeze between the gear lockers and engine 1", across=(1, 0))
    b.box(10.0, 17.3, 16.0, 17.88); b.box(20.3, 17.2, 23.88, 17.88); b.box(22.8, 14.0, 23.88, 15.5)
    b.clutter((23.88, 5.0), (23.88, 11.0), -1, 2, depth=(0.3, 0.5), length=(0.4, 0.8))
    # north rooms
    for k in range(3):
        b.box(0.3 + 2.5 * k, 24.0, 1.2 + 2.5 * k, 25.88)     # bunks
    b.box(0.12, 20.5, 0.7, 23.0); b.box(6.2, 20.12, 7.88, 20.7)
    b.box(8.12, 24.8, 13.88, 25.4); b.box(9.0, 22.9, 13.0, 23.9)   # wall lockers, locker island with bench
    b.passage(11.0, 24.35, 0.9, "locker room: aisle between the wall lockers and the locker island", across=(0, 1))
    for u in (15.0, 16.5, 18.0):
        b.box(u, 23.9, u + 0.8, 25.8)                          # treadmills
    b.box(21.6, 20.8, 23.0, 22.4); b.box(20.0, 24.9, 23.88, 25.88); b.box(19.0, 21.5, 19.5, 22.9)
    # east rooms
    b.box(33.0, 0.12, 39.88, 0.8); b.box(39.2, 0.8, 39.88, 4.0); b.chair(35.0, 1.5); b.chair(37.0, 1.4)
    b.desk(36.0, 7.9, 39.8, 8.88, "n"); b.desk(27.0, 5.12, 29.0, 6.0, "s"); b.chair(37.5, 7.4); b.box(26.12, 8.0, 27.0, 8.88)
    b.table(28.0, 12.0, 34.0, 13.2)
    for k in range(5):
        b.chair(28.6 + 1.2 * k, 11.6, ang=5); b.chair(28.6 + 1.2 * k, 13.6, ang=5)
    b.box(39.2, 9.5, 39.88, 16.5); b.box(36.0, 14.0, 37.0, 16.94); b.box(36.5, 9.12, 38.5, 9.7)
    for k in range(3):
        b.box(28.5 + 1.2 * k, 19.5, 29.3 + 1.2 * k, 20.4)      # recliners
    b.box(28.0, 25.3, 32.0, 25.88); b.box(34.5, 21.5, 37.0, 23.0); b.box(38.0, 18.0, 39.88, 20.2)
    b.outside(16)
    b.person([(6.0, 14.5), (18.0, 13.5)], speed=0.3, start=0, stop=900)
    b.person([(31.5, 15.5)], start=0, stop=2000)
    b.person([(16.9, 24.8)], start=400, stop=1500)
    # spaces
    b.space(12.5, 8.0, "room", "apparatus bay", region=(0.8, 0.6, 23.5, 17.2))
    b.space(25.0, 10.0, "hallway", "L corridor (north leg + east leg)", region=(24.2, 0.3, 25.8, 25.7))
    b.space(4.0, 22.5, "room", "bunk room", region=(0.3, 20.2, 7.8, 25.8))
    b.space(11.0, 21.7, "room", "locker / shower room", region=(8.2, 20.2, 13.8, 22.8))
    b.space(18.5, 21.8, "room", "fitness room", region=(14.2, 20.2, 23.8, 23.8))
    b.space(32.5, 2.8, "room", "watch room", region=(26.2, 0.9, 38.8, 4.8))
    b.space(32.5, 7.0, "room", "office", region=(26.2, 5.2, 35.8, 7.8))
    b.space(29.5, 15.5, "room", "kitchen / mess", group="mess", region=(26.2, 9.2, 35.8, 16.8))
    b.space(33.0, 22.0, "room", "day room", group="mess", region=(26.2, 17.2, 39.8, 25.2))
    b.route([(25.0, 1.0), (25.0, 2.5), (28.0, 2.5), (25.0, 2.5), (25.0, 4.0), (22.3, 4.3), (22.3, 2.0), (18.5, 1.4),
             (12.5, 1.3), (6.0, 1.3), (1.125, 1.5), (1.125, 14.0), (1.2, 17.0), (6.0, 14.5), (12.5, 14.5),
             (12.5, 2.0), (12.5, 14.5), (18.0, 13.2), (22.0, 13.0), (22.0, 16.5), (19.0, 16.5), (19.0, 19.4),
             (16.0, 19.4), (16.0, 21.5), (18.3, 21.2), (18.3, 23.3), (20.6, 23.3), (20.6, 20.6), (16.0, 21.0),
             (16.0, 19.4), (11.0, 19.4), (11.0, 21.5), (8.6, 22.5), (8.6, 24.35), (13.4, 24.35), (13.4, 22.5),
             (11.0, 21.5), (11.0, 19.4), (4.0, 19.4), (4.0, 19.7), (4.0, 19.4),
             (1.0, 19.4), (25.0, 19.4), (25.0, 25.3), (25.0, 22.0), (28.0, 22.0), (33.0, 21.2), (33.0, 17.0),
             (33.0, 14.6), (27.0, 14.6), (27.0, 12.0), (25.0, 12.0), (25.0, 7.0), (28.0, 7.0), (25.0, 7.0),
             (25.0, 1.0)])
    b.route([(25.0, 1.0), (25.0, 12.0), (27.2, 12.0), (27.4, 14.7), (35.0, 14.6), (35.3, 10.6), (38.3, 10.6),
             (38.3, 16.0), (38.3, 12.8), (35.0, 12.8), (35.0, 16.0), (33.0, 17.5), (36.0, 19.0), (38.0, 21.0),
             (38.0, 24.3), (30.0, 24.0), (27.5, 22.0), (25.0, 22.0), (25.0, 19.4), (6.0, 19.4), (6.0, 14.5),
             (12.5, 14.5), (18.0, 13.2), (22.3, 12.0), (22.3, 4.3), (25.0, 4.0), (25.0, 1.0)],
            bias=(0.08, 0.07, -0.5))
    return b



def bank():
    b = B("b7_bank", "Bank branch (28 x 18 m, rotated 12 deg): glass street front with a 1.6 m sliding entrance (no "
          "leaves) and a glass ATM lobby (own 1.0 m street door, 1.0 m glass door into the hall); a banking hall with "
          "queue posts, a pillar and writing desks; a teller counter across the whole hall (maps like a wall) with "
          "a 0.9 m security door at its west end into the teller area (hall + teller area grouped); three advisor "
          "offices behind a GLASS front with 0.9 m glass doors; a private-client lounge; a 1.8 m staff corridor "
          "(one hallway) with the staff entrance lobby, manager's office, staff room, a VAULT with 0.45 m walls, "
          "its door slab swung back against the corridor wall and a shelving island inside (0.9 m and 0.8 m aisles), a safe-deposit room whose cabinet island "
          "leaves a 0.8 m aisle, toilets and a fire exit. Return pass with a loop-closure error. Hard: glass "
          "front and offices, counter line, thick vault walls.", (28, 18), theta=12, seed=33)
    w = b.wall
    w((0, 0), (4, 0), glass=True, doors=[(2.0, 1.0, "ATM lobby street door (to outside)", ("a", -1, 90))])
    w((4, 0), (20, 0), glass=True, doors=[(6.0, 1.6, "main entrance (sliding, banking hall to outside)")])
    w((20, 0), (28, 0), EXT, windows=[(1.5, 6.5)])
    w((28, 0), (28, 18), EXT, doors=[(13.1, 1.0, "corridor east end: fire exit", ("a", -1, 90))])
    w((28, 18), (0, 18), EXT, windows=[(14.5, 17.5), (19.5, 22.5)])
    w((0, 18), (0, 0), EXT, doors=[(2.0, 1.0, "staff entrance (to outside)", ("a", -1, 90))])
    w((4, 0), (4, 4), glass=True, doors=[(2.0, 1.0, "ATM lobby to banking hall (glass door)", ("b", 1, 90))])
    w((0, 4), (4, 4))
    w((4, 4), (4, 9), doors=[(2.5, 0.9, "banking hall to private lounge", ("a", 1, 90))])
    w((4, 9), (4, 12.2))
    w((4, 9), (6, 9), doors=[(1.0, 0.9, "banking hall to teller area (security door)", ("a", 1, 90))])
    b.box(6.0, 8.94, 19.94, 9.6)                      # teller counter (glass screens above lidar height)
    w((20, 0), (20, 9), glass=True, doors=[(1.75, 0.9, "banking hall to advisor office 1 (glass door)", ("a", -1, 90)),
                                           (5.25, 0.9, "banking hall to advisor office 2 (glass door)", ("a", -1, 90)),
                                           (8.0, 0.9, "banking hall to advisor office 3 (glass door)", ("b", -1, 90))])
    w((20, 9), (20, 12.2))
    w((20, 3.5), (28, 3.5)); w((20, 7), (28, 7))
    w((0, 12.2), (4, 12.2))
    w((4, 12.2), (28, 12.2), doors=[(8.0, 0.9, "teller area to staff corridor", ("b", -1, 90))])
    w((4, 12.2), (4, 18), doors=[(0.9, 1.0, "staff corridor to staff entrance lobby", ("a", 1, 90))])
    w((4, 14), (14, 14), doors=[(2.5, 0.9, "corridor to manager's office", ("a", 1, 90)),
                                (7.5, 0.9, "corridor to staff room", ("b", 1, 90))])
    w((14, 14), (19, 14), 0.45, doors=[(2.5, 1.0, "corridor to vault (vault door open)")])
    b.box(15.0, 13.52, 16.0, 13.77)                  # vault door slab swung back against the corridor wall
    w((14, 14), (14, 18), 0.45); w((19, 14), (19, 18), 0.45); w((9, 14), (9, 18))
    w((19, 14), (28, 14), doors=[(2.0, 0.9, "corridor to safe-deposit room", ("b", -1, 165)),
                                 (7.0, 0.8, "corridor to toilets", ("a", 1, 90))])
    w((24, 14), (24, 18))
    # ATM lobby, lounge
    b.box(0.6, 3.3, 1.4, 3.94); b.box(1.8, 3.3, 2.6, 3.94)
    b.box(0.12, 7.5, 0.9, 10.0); b.table(1.5, 8.0, 2.5, 9.5); b.box(3.0, 10.5, 3.8, 11.3); b.box(0.12, 11.2, 1.5, 12.14)
    # banking hall
    b.box(11.7, 4.2, 12.3, 4.8)
    for u in (7.5, 8.7):
        for v in (5.0, 6.0, 7.0, 8.0):
            b.dot(u, v, 0.04)
    b.table(14.0, 3.0, 15.4, 3.6); b.table(14.0, 5.5, 15.4, 6.1)
    b.box(5.0, 0.14, 7.0, 0.6); b.rbox(17.5, 0.7, 0.6, 0.3, 0); b.box(19.3, 8.2, 19.7, 8.6)
    # teller area
    for u in (7.0, 10.0, 13.0, 16.0, 19.0):
        b.chair(u, 10.1)
    b.box(7.0, 11.6, 9.0, 12.14); b.box(14.0, 11.6, 16.0, 12.14); b.box(4.06, 11.0, 4.7, 12.14)
    # offices
    b.desk(24.0, 1.2, 25.6, 2.4, "e"); b.chair(23.5, 1.5, 20); b.box(27.3, 0.4, 27.88, 3.0)
    b.desk(24.0, 4.6, 25.6, 5.8, "e"); b.chair(23.5, 4.9, 35); b.box(26.8, 6.3, 27.88, 6.88)
    b.desk(25.0, 9.0, 26.6, 10.6, "e"); b.box(20.12, 11.5, 22.5, 12.08)
    # north rooms
    b.box(0.12, 16.8, 1.2, 17.88); b.box(2.8, 14.06, 3.88, 14.7)
    b.desk(6.5, 16.9, 8.7, 17.88, "n"); b.chair(7.5, 16.5); b.box(4.06, 16.0, 4.6, 17.88)
    b.box(9.06, 17.3, 12.5, 17.88); b.table(10.0, 15.2, 11.2, 16.2)
    b.box(14.3, 17.1, 18.7, 17.7); b.box(18.2, 14.6, 18.7, 16.6); b.box(15.5, 15.3, 17.3, 16.3)
    b.passage(17.75, 15.8, 0.9, "vault: aisle between the shelving island and the east shelves", across=(1, 0))
    b.passage(16.4, 16.7, 0.8, "vault: aisle between the shelving island and the north shelves", across=(0, 1))
    b.box(19.06, 14.6, 19.6, 17.94); b.box(20.4, 15.2, 22.0, 17.2); b.box(23.4, 15.6, 23.94, 17.94)
    b.passage(20.0, 16.2, 0.8, "safe-deposit room: aisle between the wall cabinets and the cabinet island", across=(1, 0))
    b.seg((25.3, 17.94), (25.3, 16.5), 0.05); b.seg((26.6, 17.94), (26.6, 16.5), 0.05); b.box(27.4, 14.6, 27.94, 16.0)
    b.outside(16)
    b.person([(8.1, 5.5)], start=0, stop=1200)
    b.person([(8.1, 7.4)], start=0, stop=600)
    b.person([(6.0, 3.0), (17.0, 2.0)], speed=0.3, start=100, stop=1000)
    b.person([(8.5, 10.9), (17.0, 10.9)], speed=0.25, start=500, stop=1400)
    # spaces
    b.space(2.0, 2.0, "room", "ATM lobby", region=(0.3, 0.3, 3.8, 3.2))
    b.space(12.0, 6.6, "room", "banking hall", group="hall", region=(4.5, 0.8, 19.5, 8.5))
    b.space(11.5, 11.0, "room", "teller area (behind the counter)", group="hall", region=(4.8, 9.7, 19.8, 12.0))
    b.space(2.2, 5.5, "room", "private-client lounge", region=(0.3, 4.3, 3.8, 12.0))
    b.space(22.3, 1.75, "room", "advisor office 1", region=(20.2, 0.3, 27.2, 3.3))
    b.space(22.2, 5.25, "room", "advisor office 2", region=(20.2, 3.7, 27.7, 6.8))
    b.space(22.6, 9.6, "room", "advisor office 3", region=(20.2, 7.2, 27.7, 11.4))
    b.space(10.0, 13.1, "hallway", "staff corridor", region=(4.3, 12.4, 27.7, 13.8))
    b.space(2.0, 15.2, "room", "staff entrance lobby", region=(0.3, 12.4, 3.8, 17.7))
    b.space(6.5, 15.5, "room", "manager's office", region=(4.7, 14.2, 8.8, 16.4))
    b.space(11.5, 16.0, "room", "staff room", region=(9.2, 14.2, 13.7, 17.2))
    b.space(14.85, 15.8, "room", "vault", region=(14.4, 14.4, 18.1, 17.0))
    b.space(22.7, 16.1, "room", "safe-deposit room", region=(19.7, 14.2, 23.3, 17.8))
    b.space(26.0, 15.3, "room", "toilets", region=(24.2, 14.2, 27.3, 16.4))
    b.route([(10.0, 2.0), (10.0, 0.8), (10.0, 2.0), (5.0, 2.0), (2.0, 2.0), (2.0, 1.0), (2.0, 2.0), (5.0, 2.0),
             (5.5, 6.5), (2.9, 6.5), (2.9, 10.0), (2.9, 6.5), (5.5, 6.5), (6.5, 4.0), (10.5, 3.6), (17.0, 4.5), (18.6, 1.75),
             (21.5, 1.75), (23.0, 2.1), (21.5, 1.75), (18.6, 1.75), (18.6, 5.25), (21.8, 5.25), (18.6, 5.25),
             (18.6, 8.0), (21.6, 8.0), (23.0, 10.2), (21.6, 8.0), (18.6, 8.0), (10.0, 8.45), (5.0, 8.3),
             (5.0, 10.8), (12.0, 10.8), (18.8, 10.8), (12.0, 10.8), (12.0, 13.1), (27.2, 13.1), (26.0, 13.1),
             (26.0, 15.3), (26.0, 13.1), (21.0, 13.1), (21.0, 14.7), (20.0, 15.0), (20.0, 17.4), (22.7, 17.4),
             (22.7, 15.0), (21.0, 14.7), (21.0, 13.1), (16.5, 13.1), (16.5, 14.7), (17.75, 15.1), (17.75, 16.7), (14.9, 16.7), (14.9, 15.0),
             (16.5, 14.7), (16.5, 13.1), (11.5, 13.1),
             (11.5, 15.2), (11.5, 13.1), (6.5, 13.1), (6.5, 15.5), (6.5, 13.1), (4.9, 13.1), (2.0, 13.1),
             (2.0, 16.0), (2.0, 13.1)])
    b.route([(2.0, 13.1), (12.0, 13.1), (12.0, 10.8), (5.0, 10.8), (5.0, 8.3), (10.0, 8.45), (10.5, 4.0),
             (10.0, 1.0)], bias=(-0.07, 0.06, 0.5))
    return b



def gym():
    b = B("b7_gym", "Fitness gym (34 x 22 m, rotated 58 deg, mapped with a FRONT-FACING 270 deg lidar): reception with a "
          "curved desk and juice-bar counter (1.6 m entrance double door), a 1.8 m opening onto a 26 x 14 m gym floor "
          "(two rows of cardio machines with a 0.9 m aisle between them, strength machines, pillars, a functional "
          "training rig, dumbbell racks, fire exit); north: group studio (1.6 m double door, fire exit), spin studio "
          "(bike grid), men's and women's changing rooms; west: a 1.6 m corridor (one hallway) with office, physio, "
          "massage room, a creche seen only through its door, a closed store and a staff room. People training "
          "while mapping. Return pass with a loop-closure error. Hard: cluttered open floor, blind sector behind "
          "the robot, bike grid.", (34, 22), theta=58, seed=34, fov=270.0)
    w = b.wall
    w((0, 0), (8, 0), EXT, doors=[(4.0, 1.6, "entrance double door (reception to outside)", ("d", 1, 90))])
    w((8, 0), (34, 0), EXT, windows=[(2.0, 8.0)])
    w((34, 0), (34, 22), EXT, doors=[(12.0, 1.2, "gym floor fire exit (to outside)", ("a", -1, 90))])
    w((34, 22), (0, 22), EXT, doors=[(24.0, 1.0, "group studio fire exit (to outside)", ("b", -1, 90))])
    w((0, 22), (0, 0), EXT)
    w((8, 0), (8, 22), doors=[(5.0, 1.8, "reception to gym floor (1.8 m opening)")])
    w((0, 6), (8, 6), doors=[(4.0, 1.0, "reception to west corridor", ("a", 1, 90))])
    w((3.2, 6), (3.2, 22), doors=[(2.5, 0.9, "corridor to office", ("a", 1, 90)),
                                  (7.75, 0.9, "corridor to physio room", ("b", 1, 90)),
                                  {"at": 13.0, "w": 0.9, "note": "store", "closed": True}])
    w((4.8, 6), (4.8, 22), doors=[(2.25, 0.9, "corridor to massage room", ("a", -1, 90)),
                                  (7.5, 0.9, "corridor to creche", ("b", -1, 80)),
                                  (13.25, 0.9, "corridor to staff room", ("a", -1, 90))])
    w((0, 11), (3.2, 11)); w((0, 16.5), (3.2, 16.5)); w((4.8, 10.5), (8, 10.5)); w((4.8, 16.5), (8, 16.5))
    w((8, 14), (34, 14), doors=[(5.0, 1.6, "gym floor to group studio (double door)", ("d", 1, 90)),
                                (13.0, 1.0, "gym floor to spin studio", ("a", 1, 90)),
                                (18.5, 0.9, "gym floor to men's changing room", ("b", 1, 90)),
                                (23.5, 0.9, "gym floor to women's changing room", ("a", 1, 90))])
    w((18, 14), (18, 22)); w((24, 14), (24, 22)); w((29, 14), (29, 22))
    # reception
    b.arc(6.6, 3.0, 1.0, 90, 270, th=0.45)
    b.box(0.12, 1.0, 0.5, 5.0)
    for v in (1.5, 2.5, 3.5, 4.5):
        b.dot(0.85, v, 0.05)
    # gym floor: cardio rows (0.9 m aisle), pillars, machines, rig, free weights
    for k in range(8):
        b.box(10.0 + 1.45 * k, 0.8, 10.85 + 1.45 * k, 2.7)
        b.box(10.0 + 1.45 * k, 3.6, 10.85 + 1.45 * k, 5.3)
    b.passage(15.0, 3.15, 0.9, "gym floor: aisle between the two cardio rows", across=(0, 1))
    for k in range(7):     # 0.6 m gaps between neighbouring machines: a person may or may not call them passages
        b.passage(11.15 + 1.45 * k, 1.75, 0.6, f"gap between treadmills {k + 1} and {k + 2} (optional)", across=(1, 0),
                  optional=True)
        b.passage(11.15 + 1.45 * k, 4.45, 0.6, f"gap between cross-trainers {k + 1} and {k + 2} (optional)",
                  across=(1, 0), optional=True)
    b.passage(15.5, 0.46, 0.68, "strip between the treadmill row and the window wall (optional)", across=(0, 1),
              optional=True)
    b.box(13.75, 6.75, 14.25, 7.25); b.box(23.75, 6.75, 24.25, 7.25)
    for (cu, cv, ww, hh, a) in [(11.5, 9.5, 1.2, 1.6, 15), (14.5, 10.5, 1.0, 1.8, -10), (17.5, 9.0, 1.4, 1.0, 30),
                                (20.5, 10.8, 1.2, 1.5, 0)]:
        b.rbox(cu, cv, ww, hh, a)
    for u in (26.0, 27.5, 29.0, 30.5):
        for v in (6.0, 8.0):
            b.dot(u, v, 0.06)
    b.box(33.2, 2.0, 33.88, 10.0); b.rbox(31.5, 4.0, 0.35, 1.2, 0); b.rbox(31.5, 7.0, 0.35, 1.2, 0)
    for (u, v) in [(26.0, 1.5), (27.2, 1.5), (26.0, 2.7), (27.2, 2.7)]:
        b.dot(u, v, 0.05)
    b.box(29.0, 0.4, 29.6, 1.0); b.box(8.12, 10.0, 9.0, 13.88)
    # studios
    b.box(14.0, 21.2, 17.88, 21.88); b.box(8.12, 15.0, 8.8, 18.0)
    for i in range(4):
        for j in range(3):
            b.box(18.8 + 1.3 * i, 16.0 + 1.6 * j, 19.1 + 1.3 * i, 17.0 + 1.6 * j)
    for i in range(3):
        b.passage(19.6 + 1.3 * i, 18.1, 1.0, f"spin studio: aisle {i + 1} between bike columns (optional)", across=(1, 0),
                  optional=True)
    # changing rooms
    b.box(24.06, 15.0, 24.6, 21.94); b.box(26.0, 16.5, 27.0, 19.5); b.seg((27.5, 21.94), (27.5, 20.5), 0.05)
    b.box(33.4, 15.0, 33.94, 21.94); b.box(30.8, 16.5, 31.3, 19.5); b.seg((29.06, 20.5), (30.5, 20.5), 0.05)
    # west block
    b.desk(0.2, 7.0, 1.0, 8.6, "w"); b.box(2.4, 10.3, 3.14, 10.94)
    b.box(0.3, 12.0, 1.0, 14.0); b.box(2.5, 15.8, 3.14, 16.44)
    b.box(7.0, 6.5, 7.7, 8.5); b.box(6.6, 11.0, 7.94, 11.6); b.box(5.0, 15.6, 6.0, 16.44)
    b.table(6.8, 19.5, 7.9, 20.6); b.box(4.86, 21.3, 6.5, 21.94)
    b.outside(16)
    b.person([(12.0, 7.0), (22.0, 8.0), (30.0, 11.0)], speed=0.3, start=0, stop=1500)
    b.person([(27.0, 7.0)], start=0, stop=1200)
    b.person([(32.5, 9.0)], start=300, stop=1500)
    b.person([(15.0, 18.5)], start=0, stop=1000)
    # spaces
    b.space(2.5, 3.0, "room", "reception", region=(0.8, 0.3, 5.3, 5.8))
    b.space(22.0, 7.5, "room", "gym floor", region=(9.2, 0.3, 33.0, 13.8))
    b.space(4.0, 11.0, "hallway", "west corridor", region=(3.3, 6.2, 4.7, 21.8))
    b.space(1.6, 9.4, "room", "office", region=(0.2, 6.2, 3.1, 10.8))
    b.space(1.8, 14.8, "room", "physio room", region=(0.2, 11.2, 3.1, 16.3))
    b.space(6.4, 9.2, "room", "massage room", region=(4.9, 6.2, 7.9, 10.4))
    b.space(6.4, 13.3, "room", "creche", region=(4.9, 10.6, 7.9, 16.3))
    b.space(6.2, 19.5, "room", "staff room", region=(4.9, 16.6, 7.9, 21.2))
    b.space(13.0, 18.0, "room", "group studio", region=(8.9, 14.2, 17.8, 21.0))
    b.space(21.0, 21.1, "room", "spin studio", region=(18.2, 14.2, 23.8, 21.8))
    b.space(25.3, 18.0, "room", "men's changing room", region=(24.7, 14.2, 28.8, 21.8))
    b.space(32.3, 18.0, "room", "women's changing room", region=(29.2, 14.2, 33.3, 21.8))
    b.route([(4.0, 1.0), (4.0, 5.0), (9.5, 5.0), (9.4, 3.15), (22.0, 3.15), (23.5, 3.15), (25.0, 4.5), (28.5, 4.5),
             (32.5, 5.5), (32.5, 12.0), (33.4, 12.0), (32.5, 12.0), (26.5, 12.8), (26.5, 14.8), (25.3, 15.8),
             (25.3, 20.8), (25.3, 15.8), (26.5, 14.8), (26.5, 12.8), (31.5, 12.8), (31.5, 15.5), (32.3, 17.0),
             (32.3, 20.0), (32.3, 17.0), (31.5, 15.5), (31.5, 12.8), (21.0, 12.8), (20.9, 15.2), (20.9, 21.3),
             (20.9, 15.2), (21.0, 12.8), (13.0, 12.8), (13.0, 16.0), (16.0, 18.0), (10.0, 20.5), (10.0, 21.3),
             (11.0, 18.0), (13.0, 16.0), (13.0, 12.8), (9.6, 12.0), (9.6, 5.0), (4.0, 5.0), (4.0, 8.5), (1.6, 8.5),
             (1.6, 9.8), (1.6, 8.5), (4.0, 8.5), (4.0, 8.25), (6.4, 8.25), (6.4, 9.5), (6.4, 8.25), (4.0, 8.25),
             (4.0, 13.5), (4.3, 13.5), (4.0, 13.75), (1.6, 13.75), (1.6, 15.2), (1.6, 13.75), (4.0, 13.75),
             (4.0, 19.25), (6.2, 19.25), (6.2, 21.0), (6.2, 19.25), (4.0, 19.25), (4.0, 21.2), (4.0, 7.0),
             (4.0, 5.0), (4.0, 1.0)])
    b.route([(4.0, 1.0), (4.0, 5.0), (9.5, 5.0), (9.6, 12.0), (13.0, 12.8), (31.5, 12.8), (32.5, 12.0), (32.5, 5.5),
             (28.5, 4.5), (25.0, 4.5), (23.5, 5.8), (18.0, 6.3), (10.0, 6.3)], bias=(0.06, 0.08, -0.45))
    return b



def pod(b, pu, pv):
    """Eight call-centre desks back to back (4 x 2, 1.6 x 0.8 m each) with floor-standing screens, chairs."""
    for i in range(4):
        b.table(pu + 1.6 * i, pv - 0.8, pu + 1.6 * (i + 1), pv)
        b.table(pu + 1.6 * i, pv, pu + 1.6 * (i + 1), pv + 0.8)
        b.chair(pu + 0.8 + 1.6 * i, pv - 1.15); b.chair(pu + 0.8 + 1.6 * i, pv + 1.15)
    b.seg((pu, pv), (pu + 6.4, pv), 0.04)
    for i in range(5):
        b.seg((pu + 1.6 * i, pv - 0.8), (pu + 1.6 * i, pv + 0.8), 0.04)


def call_centre():
    b = B("b7_call_centre", "Call centre (38 x 20 m, rotated -71 deg): a 26 x 16 m open-plan floor with eight desk pods "
          "(back-to-back desks with floor-standing screens, chairs) and a ring-shaped supervisor desk, staff lockers "
          "along the west wall leaving a 0.88 m slot beside a pod, a fire exit; along its north side a training room "
          "(solid wall, seen only through its door), three GLASS-fronted meeting rooms with glass doors (the glass hardly "
          "mapped: doors optional, rooms grouped with the floor as alcoves) and a focus "
          "room; east: a 1.9 m corridor (one hallway) entered from the lobby through a 1.2 m security door, with a 1.6 m "
          "double door and a 1.0 m door to the floor, a breakout kitchen behind a 2.0 m opening, toilets and a quiet "
          "room (seen through its door); reception lobby with a 1.6 m entrance double door and a 1.0 m door to the "
          "floor. Return pass with a loop-closure error. Hard: endless desk clutter, glass fronts.",
          (38, 20), theta=-71, seed=35)
    w = b.wall
    w((0, 0), (26, 0), EXT, windows=[(1.0, 7.0), (17.0, 25.0)])
    w((26, 0), (38, 0), EXT, doors=[(6.0, 1.6, "main entrance double door (lobby to outside)", ("d", 1, 90))])
    w((38, 0), (38, 20), EXT)
    w((38, 20), (0, 20), EXT, windows=[(28.5, 31.5)])
    w((0, 20), (0, 0), EXT, doors=[(7.5, 1.0, "open floor west fire exit (to outside)", ("a", -1, 90))])
    w((26, 0), (26, 20), doors=[(2.5, 1.0, "lobby to open floor", ("a", -1, 90)),
                                (8.0, 1.6, "corridor to open floor (double door)", ("d", 1, 90)),
                                (14.0, 1.0, "corridor to open floor (north door)", ("b", 1, 90))])
    w((26, 5), (38, 5), doors=[(1.0, 1.2, "lobby to corridor (security door)", ("a", 1, 90))])
    w((28, 5), (28, 20), doors=[(3.0, 2.0, "corridor to breakout kitchen (2.0 m opening)"),
                                (7.5, 0.9, "corridor to men's toilets", ("a", -1, 90)),
                                (10.5, 0.9, "corridor to women's toilets", ("b", -1, 90)),
                                (13.5, 0.9, "corridor to quiet room", ("a", -1, 85))])
    w((28, 11), (38, 11)); w((28, 14), (38, 14)); w((28, 17), (38, 17))
    w((0, 16), (8, 16), doors=[(6.0, 1.0, "open floor to training room", ("b", 1, 95))])
    w((8, 16), (22, 16), glass=True, doors=[(2.5, 0.9, "open floor to meeting room A (glass door)", ("a", 1, 90)),
                                            (7.5, 0.9, "open floor to meeting room B (glass door)", ("a", 1, 90)),
                                            (12.0, 0.9, "open floor to meeting room C (glass door)", ("a", 1, 90))])
    w((22, 16), (26, 16), doors=[(2.0, 0.9, "open floor to focus room", ("a", 1, 90))])
    for u in (8, 13, 18, 22):
        w((u, 16), (u, 20))
    # open floor
    for (pu, pv) in [(1.5, 3.0), (9.7, 3.0), (17.9, 3.0), (1.5, 8.0), (17.9, 8.0), (1.5, 13.0), (9.7, 13.0),
                     (17.9, 13.0)]:
        pod(b, pu, pv)
    b.arc(12.9, 8.0, 1.3, 20, 340, th=0.5)
    b.box(0.12, 5.0, 0.6, 11.0)
    b.passage(1.04, 8.0, 0.88, "open floor: slot between the staff lockers and the west desk pod", across=(1, 0))
    b.box(24.9, 11.4, 25.5, 12.4); b.box(25.3, 15.2, 25.94, 15.94)
    b.passage(25.72, 11.9, 0.44, "open floor: squeeze between the copier and the east wall (optional)", across=(1, 0),
              optional=True)
    # north rooms
    for k in range(3):
        b.table(1.0 + 2.2 * k, 17.0, 2.8 + 2.2 * k, 17.7)
    b.table(9.2, 17.6, 11.8, 18.6); b.chair(8.7, 18.1); b.chair(12.3, 18.1)
    b.table(14.2, 17.6, 16.8, 18.6); b.chair(13.7, 18.1); b.chair(17.3, 18.1)
    b.table(19.0, 17.6, 21.0, 18.6); b.chair(21.5, 18.1)
    b.box(25.2, 16.8, 25.94, 19.5)
    # east rooms
    b.box(34.0, 1.5, 36.5, 2.2); b.box(28.3, 3.5, 29.8, 4.4); b.box(37.3, 0.5, 37.88, 4.5)
    b.box(37.3, 5.5, 37.88, 10.5); b.table(32.5, 6.2, 33.3, 7.0); b.table(33.5, 9.0, 34.3, 9.8)
    b.chair(32.9, 5.8); b.chair(33.9, 10.2)
    for u in (35.0, 36.5):
        b.seg((u, 11.06), (u, 12.6), 0.05); b.seg((u, 13.94), (u, 12.4), 0.05)
        b.seg((u, 14.06), (u, 15.6), 0.05); b.seg((u, 16.94), (u, 15.4), 0.05)
    b.box(28.06, 11.3, 28.6, 11.9); b.box(28.06, 16.2, 28.6, 16.8)
    b.box(34.5, 19.1, 37.88, 19.88); b.box(37.2, 17.06, 37.88, 18.5)
    b.outside(16)
    b.person([(5.0, 5.5), (22.0, 5.5)], speed=0.3, start=0, stop=1200)
    b.person([(16.2, 10.4)], start=0, stop=2000)
    b.person([(4.2, 15.0)], start=200, stop=900)
    b.person([(27.0, 9.0), (27.0, 18.0)], speed=0.25, start=600, stop=1400)
    # spaces
    b.space(13.0, 5.5, "room", "open-plan floor", group="floor", region=(0.7, 0.3, 25.7, 15.7))
    b.space(31.0, 2.2, "room", "reception lobby", region=(26.2, 0.3, 37.0, 4.8))
    b.space(27.0, 11.0, "hallway", "corridor", region=(26.1, 5.2, 27.9, 19.8))
    b.space(4.0, 18.4, "room", "training room", region=(0.3, 16.2, 7.8, 19.8))
    b.space(10.5, 16.9, "room", "meeting room A (glass front barely mapped: grouped with the floor)", group="floor", region=(8.2, 16.2, 12.8, 19.8))
    b.space(15.5, 16.9, "room", "meeting room B (glass front barely mapped: grouped with the floor)", group="floor", region=(13.2, 16.2, 17.8, 19.8))
    b.space(19.8, 16.9, "room", "meeting room C (glass front barely mapped: grouped with the floor)", group="floor", region=(18.2, 16.2, 21.8, 19.8))
    b.space(23.9, 18.0, "room", "focus room", region=(22.2, 16.2, 25.1, 19.8))
    b.space(30.5, 8.0, "room", "breakout kitchen", region=(28.2, 5.2, 37.1, 10.8))
    b.space(31.0, 12.5, "room", "men's toilets", region=(28.7, 11.2, 34.8, 13.8))
    b.space(31.0, 15.5, "room", "women's toilets", region=(28.7, 14.2, 34.8, 16.8))
    b.space(32.0, 18.4, "room", "quiet room", region=(28.2, 17.2, 37.0, 19.0))
    b.route([(32.0, 1.2), (32.0, 3.0), (27.1, 2.8), (27.1, 8.0), (24.9, 8.0), (25.1, 10.5), (9.0, 10.5), (1.05, 10.5),
             (1.05, 5.5), (0.8, 4.5), (0.8, 0.85), (25.0, 0.85), (25.1, 5.5), (17.0, 5.5), (17.0, 15.2), (15.5, 15.2),
             (15.5, 17.0), (15.5, 15.2), (10.5, 15.2), (10.5, 17.0), (10.5, 15.2), (6.0, 15.2), (6.0, 15.6),
             (6.0, 15.2), (1.0, 15.2), (0.9, 12.5), (0.9, 15.2), (20.0, 15.2), (20.0, 17.0), (20.0, 15.2),
             (24.0, 15.2), (24.0, 17.6), (24.0, 15.2), (25.1, 14.0), (27.1, 14.0), (27.1, 19.2), (27.1, 18.5),
             (27.4, 18.5), (27.1, 15.5), (29.5, 15.5), (31.5, 15.5), (29.5, 15.5), (27.1, 15.5), (27.1, 12.5),
             (31.5, 12.5), (27.1, 12.5), (27.1, 8.0), (30.0, 8.0), (36.3, 8.0), (30.0, 8.0), (27.1, 8.0),
             (27.1, 2.8), (32.0, 3.0)])
    b.route([(32.0, 3.0), (27.1, 2.8), (27.1, 8.0), (24.9, 8.0), (25.1, 10.5), (17.0, 10.5), (17.0, 5.5), (8.8, 5.5),
             (8.8, 10.5), (8.8, 15.2), (17.0, 15.2), (17.0, 10.5), (25.1, 10.5)], bias=(0.1, -0.08, 0.6))
    return b



def church():
    b = B("b7_church", "Parish church (30 x 20 m, rotated 3.5 deg, mapped with a FRONT-FACING 270 deg lidar): a narthex "
          "(1.8 m west double door; a 1.8 m double door and two 0.9 m side doors into the nave) with the parish office "
          "and toilets off it; an 18 x 12 m nave with 30 pews (0.35 m gaps: too tight for the robot, no passages), "
          "pilasters, side chapels behind 2.4 m ARCHES (optional door entries), a store seen only through its door, "
          "a choir vestry, a cry room with a glass window into the nave, a parish hall; a chancel behind a communion "
          "rail that maps like a wall with a 0.9 m gate (passage; nave, chancel and both chapels grouped 'church'); "
          "north and south sacristies off the chancel (south one with an outside door). Return pass with a "
          "loop-closure error. Hard: pew rows, arches, rail gate, blind sector behind the robot.",
          (30, 20), theta=3.5, seed=36, fov=270.0)
    w = b.wall
    w((0, 0), (30, 0), EXT, doors=[(28.0, 1.0, "south sacristy outside door", ("a", -1, 90))])
    w((30, 0), (30, 20), EXT)
    w((30, 20), (0, 20), EXT, doors=[(10.0, 1.2, "parish hall outside door", ("b", -1, 90))])
    w((0, 20), (0, 0), EXT, doors=[(10.0, 1.8, "main west double door (narthex to outside)", ("d", -1, 90))])
    w((0, 4), (22, 4), doors=[(2.0, 0.9, "narthex to parish office", ("a", -1, 90)),
                              {"at": 8.5, "w": 2.4, "note": "2.4 m arch: nave to south chapel (optional)", "optional": True},
                              (13.5, 0.9, "nave to store", ("a", -1, 90)),
                              (19.0, 0.9, "nave to choir vestry", ("b", -1, 90))])
    w((0, 16), (22, 16), doors=[(2.0, 0.9, "narthex to toilets", ("b", 1, 90)),
                                {"at": 8.5, "w": 2.4, "note": "2.4 m arch: nave to north chapel (optional)", "optional": True},
                                (13.0, 0.9, "nave to cry room", ("a", 1, 90)),
                                (18.5, 1.2, "nave to parish hall", ("b", 1, 90))], windows=[(11.3, 12.5)])
    w((4, 4), (4, 16), doors=[(2.0, 0.9, "narthex to nave (south side door)", ("a", -1, 90)),
                              (6.0, 1.8, "narthex to nave (double door)", ("d", -1, 90)),
                              (10.0, 0.9, "narthex to nave (north side door)", ("a", -1, 90))])
    for u in (6, 11, 16):
        w((u, 0), (u, 4))
    for u in (6, 11, 15):
        w((u, 16), (u, 20))
    w((22, 0), (22, 6)); w((22, 14), (22, 20), doors=[(4.0, 0.9, "parish hall to north sacristy", ("a", -1, 90))])
    w((22, 6), (30, 6), doors=[(2.0, 0.9, "chancel to south sacristy", ("a", -1, 90))])
    w((22, 14), (30, 14), doors=[(2.0, 0.9, "chancel to north sacristy", ("b", 1, 90))])
    w((26, 6), (26, 14))
    # communion rail (furniture) with a 0.9 m gate
    b.seg((22.0, 6.0), (22.0, 9.55), 0.08); b.seg((22.0, 10.45), (22.0, 14.0), 0.08)
    b.passage(22.0, 10.0, 0.9, "communion rail gate (nave to chancel)", across=(0, 1))
    # nave: pews, pilasters
    for k in range(15):
        u = 6.5 + 0.85 * k
        b.box(u, 6.8, u + 0.5, 9.2); b.box(u, 10.8, u + 0.5, 13.2)
    for u in (6.3, 10.7, 15.5, 20.5):
        b.box(u - 0.3, 4.06, u + 0.3, 4.5); b.box(u - 0.3, 15.5, u + 0.3, 15.94)
    # narthex, office, toilets
    b.box(0.12, 6.5, 0.6, 8.5); b.box(0.12, 12.0, 0.6, 14.5); b.dot(3.5, 8.6, 0.2); b.dot(3.5, 11.4, 0.2)
    b.desk(3.5, 0.2, 5.8, 1.0, "s"); b.chair(4.5, 1.5); b.box(0.12, 0.5, 0.6, 3.0)
    b.seg((3.5, 19.94), (3.5, 18.6), 0.05); b.seg((5.0, 19.94), (5.0, 18.6), 0.05); b.box(0.12, 16.5, 0.6, 18.0)
    # chapels, store, vestry, cry room, parish hall
    b.box(8.0, 0.3, 9.0, 0.8); b.box(7.2, 1.5, 9.8, 1.8)
    b.box(8.2, 19.2, 8.8, 19.88); b.box(6.5, 18.0, 7.5, 18.4)
    b.passage(6.28, 18.2, 0.44, "north chapel: squeeze between the candle stand and the wall (optional)", across=(1, 0),
              optional=True)
    b.box(11.12, 0.12, 15.88, 0.7); b.box(15.3, 1.0, 15.88, 3.5)
    b.box(16.12, 0.12, 21.88, 0.6); b.box(20.0, 2.5, 21.5, 3.2)
    b.box(11.12, 19.2, 14.88, 19.88); b.chair(14.2, 17.5)
    b.box(15.2, 19.0, 17.5, 19.88); b.table(19.6, 17.0, 21.2, 18.2)
    # chancel, sacristies
    b.box(24.0, 9.0, 25.0, 11.0); b.box(22.6, 7.0, 23.0, 7.4); b.box(25.5, 9.6, 25.94, 10.4)
    b.dot(25.3, 12.6, 0.03); b.dot(25.7, 12.6, 0.03); b.dot(25.3, 13.0, 0.03); b.dot(25.7, 13.0, 0.03)
    b.box(29.3, 14.5, 29.88, 19.5); b.box(22.8, 19.3, 27.0, 19.88); b.table(26.5, 15.5, 28.0, 16.3)
    b.box(29.3, 0.5, 29.88, 5.5); b.box(22.12, 0.12, 25.0, 0.7)
    b.outside(16)
    b.person([(6.0, 10.0), (20.0, 10.0)], speed=0.2, start=0, stop=900)
    b.person([(9.0, 5.3)], start=0, stop=1300)
    b.person([(12.5, 14.3)], start=500, stop=1500)
    # spaces
    b.space(2.0, 12.8, "room", "narthex", region=(0.8, 4.2, 3.8, 15.8))
    b.space(2.3, 2.4, "room", "parish office", region=(0.7, 1.2, 5.8, 3.8))
    b.space(2.0, 17.4, "room", "toilets", region=(0.7, 16.2, 5.8, 18.5))
    b.space(12.5, 10.0, "room", "nave", group="church", region=(5.0, 4.7, 21.5, 15.3))
    b.space(23.0, 12.2, "room", "chancel (behind the communion rail)", group="church", region=(22.2, 6.2, 25.8, 13.8))
    b.space(8.5, 3.0, "room", "south side chapel", group="church", region=(6.2, 1.9, 10.8, 3.8))
    b.space(9.3, 18.0, "room", "north side chapel", group="church", region=(6.2, 16.2, 10.8, 19.1))
    b.space(13.5, 2.0, "room", "store", region=(11.2, 0.8, 15.2, 3.8))
    b.space(18.5, 2.2, "room", "choir vestry", region=(16.2, 0.7, 21.8, 3.8))
    b.space(13.0, 17.8, "room", "cry room", region=(11.2, 16.2, 14.8, 19.1))
    b.space(17.5, 17.5, "room", "parish hall", region=(15.2, 16.2, 21.8, 18.9))
    b.space(25.0, 16.8, "room", "north sacristy", region=(22.2, 14.2, 29.2, 19.2))
    b.space(26.0, 3.0, "room", "south sacristy", region=(22.2, 0.8, 29.2, 5.8))
    b.route([(2.0, 10.0), (0.9, 10.0), (2.0, 10.0), (2.0, 4.8), (2.0, 2.0), (4.0, 2.2), (2.0, 2.0), (2.0, 4.8),
             (2.0, 15.2), (2.0, 17.8), (2.0, 15.2), (2.0, 10.0), (5.5, 10.0), (5.5, 5.6), (8.5, 5.6), (8.5, 3.2),
             (8.5, 5.6), (13.5, 5.6), (13.5, 4.7), (13.5, 5.6), (19.0, 5.6), (19.0, 2.0), (19.0, 5.6), (20.5, 5.6),
             (20.5, 10.0), (23.0, 10.0), (23.0, 12.5), (24.0, 13.0), (24.0, 15.5), (26.0, 17.5), (24.0, 15.5),
             (24.0, 13.0), (23.0, 12.5), (23.3, 8.0), (24.0, 7.2), (24.0, 4.5), (26.0, 2.5), (28.0, 1.0),
             (26.0, 2.5), (24.0, 4.5), (24.0, 7.2), (23.3, 8.0), (23.0, 10.0), (20.5, 10.0), (20.5, 14.4),
             (18.5, 14.4), (18.5, 17.8), (16.5, 17.8), (18.5, 17.8), (18.5, 14.4), (13.0, 14.4), (13.0, 17.5),
             (13.0, 14.4), (8.5, 14.4), (8.5, 18.0), (8.5, 14.4), (5.5, 14.4), (5.5, 10.0), (2.0, 10.0)])
    b.route([(2.0, 10.0), (5.5, 10.0), (20.5, 10.0), (20.5, 5.6), (5.5, 5.6), (5.5, 10.0), (2.0, 10.0)],
            bias=(-0.08, 0.07, 0.5))
    return b


BUILDINGS = [kindergarten, fire_station, bank, gym, call_centre, church]
