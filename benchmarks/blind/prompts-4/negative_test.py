#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.library()
LA = (0.8, 10.2, 0)
bad = [
    [ntp(circ(6.0, 11.3, 0.75), spaces=["C"])],                          # door circle restricted to the corridor
    [ntp(poly(11.9, 1.0, 12.3, 8.0), spaces=["RR"])],                   # region almost all inside a wall
    [ntp(mb.band(16.5, 9.2, 18.5, 11.2), spaces=["C"], kind="frontier")],  # frontier strip 2 m deep
    [ntp(poly(15.0, 7.0, 17.5, 9.0), spaces=["ST"], kind="through:Q1")],   # 'through' far from its door
]
for exp in bad:
    try:
        bld_check.check(b, [("A", LA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:90])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
