#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from the
previous round's negative_test.py to the data centre)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
from bld_geom import band
b, C = mb.datacentre()
PA = (6.8, 3.9, 0)
bad = [
    [ntp(circ(13.1, 2.9, 0.75), spaces=["HW"])],                               # door circle limited to the corridor
    [ntp(poly(10.95, 0.2, 11.25, 2.6), spaces=["UPS"])],                       # region in the wall between two rooms
    [ntp(band(12.15, 12.9, 25.85, 14.45), spaces=["DH"], kind="frontier")],    # frontier strip 1.7 m deep
    [ntp(poly(17.5, 5.2, 20.5, 7.5), spaces=["DH"], kind="through:NOCD")],     # 'through' too far from its door
    [ntp(poly(11.4, 0.2, 14.8, 2.6), spaces=["UPS"])],                         # the wrong room (BAT, not UPS)
    [ntp(poly(14.0, 3.2, 16.0, 6.5), spaces=["HW"])],                          # data-hall cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", PA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
