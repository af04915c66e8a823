#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.courthouse()
CA = (1.0, 12.0, 0)
bad = [
    [ntp(circ(7.5, 13.1, 0.75), spaces=["WK"])],                             # door circle limited to the corridor
    [ntp(poly(9.8, 8.0, 10.0, 11.0), spaces=["CH"])],                        # region in a wall
    [ntp(mb.band(6.0, 6.1, 7.95, 7.9), spaces=["RR"], kind="frontier")],     # frontier strip 2 m deep
    [ntp(poly(5.5, 6.5, 8.0, 8.5), spaces=["RR"], kind="through:RR")],       # 'through' too far from its door
    [ntp(poly(0.5, 6.5, 4.5, 10.5), spaces=["RR"])],                         # the wrong room (CL, not RR)
    [ntp(poly(13.2, 6.0, 15.0, 7.5), spaces=["CH"])],                        # foyer cells called the hall
]
for exp in bad:
    try:
        bld_check.check(b, [("A", CA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
