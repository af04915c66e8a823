#!/usr/bin/env python3
"""Negative test of the region check: deliberately wrong expectations must be rejected (adapted from the
eighth blind set to the recording studio)."""
import make_buildings as mb, bld_check
from bld_lib import ntp, poly, circ
b, C = mb.studio()
PA = (7.8, 2.9, 0)
bad = [
    [ntp(circ(11.5, 1.9, 0.75), spaces=["HW"])],                              # door circle limited to the corridor
    [ntp(poly(9.85, 0.2, 9.95, 1.6), spaces=["VB1"])],                        # region in the wall between the booths
    [ntp(mb.band(8.1, 10.45, 12.85, 11.85), spaces=["AR"], kind="frontier")], # frontier strip 1.45 m deep
    [ntp(poly(8.0, 4.1, 11.0, 6.3), spaces=["CR"], kind="through:CRD")],      # 'through' too far from its door
    [ntp(poly(10.2, 0.2, 12.8, 1.6), spaces=["VB1"])],                        # the wrong booth (VB2, not VB1)
    [ntp(poly(14.0, 4.5, 16.0, 6.5), spaces=["HW"])],                         # live-room cells called the corridor
]
for exp in bad:
    try:
        bld_check.check(b, [("A", PA, "negative test", exp)])
    except AssertionError as e:
        print("rejected as it should be:", str(e)[:110])
    else:
        raise SystemExit("NOT rejected: %r" % exp)
