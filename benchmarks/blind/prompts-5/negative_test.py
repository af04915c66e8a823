#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.restaurant()
RA = (12.1, 0.8, 90)
bad = [
    [ntp(circ(13.1, 5.5, 0.75), spaces=["H"])],                              # door circle limited to the hallway
    [ntp(poly(10.9, 1.0, 11.3, 9.0), spaces=["DR"])],                        # region almost all in a wall
    [ntp(mb.band(16.5, 7.4, 18.5, 11.3), spaces=["E3"], kind="frontier")],  # frontier strip 2 m deep
    [ntp(poly(15.0, 7.4, 17.5, 9.5), spaces=["E3"], kind="through:E3")],    # 'through' too far from its door
    [ntp(poly(13.2, 4.0, 16.5, 7.0), spaces=["E3"])],                        # the wrong room
]
for exp in bad:
    try:
        bld_check.check(b, [("A", RA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:100])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
