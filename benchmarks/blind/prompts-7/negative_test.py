#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from the
sixth blind set to the fire station)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.firestation()
FA = (4.9, 12.8, 90)
bad = [
    [ntp(circ(3.9, 19.3, 0.75), spaces=["HW"])],                              # door circle limited to the corridor
    [ntp(poly(10.05, 13.0, 10.15, 18.0), spaces=["DY"])],                     # region in a wall
    [ntp(mb.band(6.15, 22.0, 9.85, 24.45), spaces=["OF"], kind="frontier")],  # frontier strip 2.5 m deep
    [ntp(poly(6.0, 20.5, 9.0, 23.5), spaces=["OF"], kind="through:OF")],      # 'through' too far from its door
    [ntp(poly(0.3, 13.6, 3.6, 16.8), spaces=["D2"])],                         # the wrong room (D1, not D2)
    [ntp(poly(4.2, 10.5, 5.6, 13.5), spaces=["HW"])],                         # bay cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", FA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
