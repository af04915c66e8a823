"""The C allocator's thresholds, set once for analyses of grid-sized arrays (glibc only).

An analysis makes and drops hundreds of temporary arrays the size of the grid (masks, distance
maps, labellings: from a hundred kilobytes on a small map to 25 MB on a 3-million-cell one).
glibc's ``malloc`` serves a block above its *mmap threshold* with fresh pages from the kernel
and gives them back when it is freed, and hands the top of its heap back to the kernel when
more than its *trim threshold* lies free there. Both start at 128 kB (the mmap threshold rises
as big blocks are freed, up to 32 MB), so nearly every such array is paid for in page faults,
the kernel zeroing every page anew: 9,000 faults and 0.12 s of kernel time in each analysis of
the 3.1-million-cell strands_aaf_y4_cropped, about a tenth of its time, and ~1,600 faults in
each analysis of a small map.

:func:`keep_freed_arrays` raises both, so freed arrays stay in the process for the next one: a
process keeps the memory of its largest analysis (its peak, which it needed anyway) instead of
asking the kernel for it again. It leaves the allocator alone where it is not glibc's, or where
the user tuned it (``MALLOC_*_`` environment variables, ``GLIBC_TUNABLES``).
"""

from __future__ import annotations

import ctypes
import functools
import logging
import os
import platform
from typing import Final

log = logging.getLogger(__name__)

#: ``mallopt`` parameter numbers (glibc's <malloc.h>).
M_TRIM_THRESHOLD: Final = -1
M_MMAP_THRESHOLD: Final = -3
#: Blocks up to this size come from the heap, reused once freed: glibc's own upper bound for
#: the threshold on 64-bit systems (32 MB), above every array of a 3-million-cell map's
#: analysis.
MMAP_THRESHOLD_BYTES: Final = 32 * 1024 * 1024
#: Free memory at the heap's top is given back only above this (bytes): more than a large
#: map's analysis frees at its end, so the pages stay for the next one (the peak of such an
#: analysis is ~260 MB, within the 500 MB the analysis may use).
TRIM_THRESHOLD_BYTES: Final = 512 * 1024 * 1024
#: Environment variables through which a user tunes glibc's allocator (left as they set it).
USER_SETTINGS: Final = ("MALLOC_MMAP_THRESHOLD_", "MALLOC_TRIM_THRESHOLD_", "MALLOC_TOP_PAD_",
                        "MALLOC_MMAP_MAX_", "GLIBC_TUNABLES")


def _user_tuned() -> bool:
    return any(name in os.environ for name in USER_SETTINGS)


@functools.cache
def keep_freed_arrays() -> bool:
    """Raise glibc's mmap and trim thresholds (see module doc), once per process. Returns
    whether they were set (False off glibc, or when the user set the allocator's own)."""
    if platform.system() != "Linux" or platform.libc_ver()[0] != "glibc" or _user_tuned():
        return False
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    ok = bool(mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES)) and bool(mallopt(M_TRIM_THRESHOLD, TRIM_THRESHOLD_BYTES))
    if not ok:
        log.debug("glibc refused the analysis's allocator thresholds; left as they were")
    return ok


__all__ = ["keep_freed_arrays"]
