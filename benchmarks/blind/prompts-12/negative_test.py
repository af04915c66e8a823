#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from round 11's
negative_test.py to the brewery)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
from bld_geom import band
b, C = mb.brewery()
PA = (10.8, 3.8, 0)
bad = [
    [ntp(circ(16.0, 2.9, 0.75), spaces=["HW"])],                               # door circle limited to the corridor
    [ntp(poly(17.95, 0.2, 18.25, 2.6), spaces=["CS"])],                        # region in the wall between two rooms
    [ntp(band(10.35, 14.9, 27.85, 16.45), spaces=["BH"], kind="frontier")],    # frontier strip 1.7 m deep
    [ntp(poly(13.0, 8.0, 16.0, 10.0), spaces=["BH"], kind="through:BHD")],     # 'through' too far from its door
    [ntp(poly(14.2, 0.2, 17.8, 2.6), spaces=["OF"])],                          # the wrong room (CS, not OF)
    [ntp(poly(13.0, 4.0, 15.0, 6.5), spaces=["HW"])],                          # brewhouse cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", PA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
