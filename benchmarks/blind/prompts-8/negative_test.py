#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from the
seventh blind set to the police station)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.police()
PA = (8.8, 3.0, 0)
bad = [
    [ntp(circ(14.35, 1.9, 0.75), spaces=["HW"])],                             # door circle limited to the corridor
    [ntp(poly(15.55, 0.2, 15.65, 1.6), spaces=["C3"])],                       # region in a wall
    [ntp(mb.band(21.3, 0.15, 23.75, 1.65), spaces=["EV"], kind="frontier")],  # frontier strip 2.5 m deep
    [ntp(poly(19.0, 4.3, 21.4, 7.9), spaces=["IR1"], kind="through:IR1")],    # 'through' too far from its door
    [ntp(poly(10.8, 0.2, 12.9, 1.6), spaces=["C1"])],                         # the wrong cell (C2, not C1)
    [ntp(poly(11.0, 3.0, 13.0, 5.0), spaces=["HW"])],                         # squad-room cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", PA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
