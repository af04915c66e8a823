#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from
prompts-11's negative_test.py to the veterinary practice)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
from bld_geom import band
b, C = mb.vet()
PA = (8.8, 3.9, 0)
bad = [
    [ntp(circ(14.1, 2.9, 0.75), spaces=["HW"])],                               # door circle limited to the corridor
    [ntp(poly(15.9, 0.2, 16.3, 2.6), spaces=["CR2"])],                         # region in the wall between two rooms
    [ntp(band(21.0, 0.15, 22.85, 2.65), spaces=["XR"], kind="frontier")],      # frontier strip 1.85 m deep
    [ntp(poly(17.5, 8.5, 20.5, 10.5), spaces=["KN"], kind="through:KND")],     # 'through' too far from its door
    [ntp(poly(16.4, 0.2, 18.0, 2.6), spaces=["CR2"])],                         # the wrong room (PH, not CR2)
    [ntp(poly(12.0, 3.2, 13.0, 6.0), spaces=["HW"])],                          # treatment-room cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", PA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
