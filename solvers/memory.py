"""Keep freed memory in the process instead of handing it back to the OS after every array.

Measured on this project's 2-core VM: a dyad over 3600 positions allocates a few dozen
57 kB arrays. glibc returns the top of its heap to the OS whenever more than 128 kB is
free, so the next allocation faults fresh pages in again, and in a virtual machine a
page fault costs more than the arithmetic on the page: the full pos+vel+acc solve ran
2.5× slower than with the heap kept (1.37 ms vs 0.66 ms for the four-bar, see
docs/performance.md). Raising glibc's trim and mmap thresholds keeps the pages mapped.
Elsewhere (no glibc) this does nothing.
"""

from __future__ import annotations

import ctypes
import ctypes.util

M_TRIM_THRESHOLD = -1
M_TOP_PAD = -2
M_MMAP_THRESHOLD = -3


def keep_freed_memory(trim: int = 64 << 20, mmap: int = 32 << 20) -> bool:
    """Ask glibc to keep up to ``trim`` bytes of freed heap; True when it agreed."""
    name = ctypes.util.find_library("c")
    if not name:
        return False
    try:
        libc = ctypes.CDLL(name)
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    ok = mallopt(M_TRIM_THRESHOLD, trim) and mallopt(M_TOP_PAD, 16 << 20)
    return bool(ok and mallopt(M_MMAP_THRESHOLD, mmap))
