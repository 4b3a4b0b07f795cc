"""Borrowed arrays: views that numba does not reference-count.

numba counts references to an array's memory (its *meminfo*) with atomic increments and
decrements, and a compiled function does so for every array it binds: each array argument of a
called function, each array an inlined function takes, each array taken out of a tuple.  Its
pruning pass removes the pairs in simple code, not in the modal engine's searches, whose loops
call functions that take a configuration tuple and half a dozen state arrays at every
evaluation of a flight: the counts were 28 % of a 10-mode run's time (benchmark 10) and 46 % of
the one-mode curve's (benchmark 6), measured with ``perf``, the calls located with ``gdb``.

A *borrowed* view (:func:`borrowed`) shares the array's data, shape and strides and has no
meminfo, so numba's count of it is a null test.  It does not keep the memory alive: whoever
makes one keeps the owning array alive for as long as the view is used (the owning array is an
argument of a function that is still running, or sits in a list that outlives the views).
Slices of a borrowed view are borrowed too.
"""

from __future__ import annotations

from numba import types
from numba.extending import intrinsic

from ..._compiled import compiled


@intrinsic
def borrowed(typingctx, arr):
    """A view of the array ``arr`` (same type, data, shape and strides) without its meminfo and
    parent object: numba does not count references to it.  The caller keeps ``arr`` alive."""
    if not isinstance(arr, types.Array):
        return None

    def codegen(context, builder, sig, args):
        src = context.make_array(arr)(context, builder, value=args[0])
        dst = context.make_array(arr)(context, builder)
        for name in ("nitems", "itemsize", "data", "shape", "strides"):
            setattr(dst, name, getattr(src, name))
        dst.meminfo = context.get_constant_null(types.MemInfoPointer(arr.dtype))
        dst.parent = context.get_constant_null(types.pyobject)
        return dst._getvalue()

    return arr(arr), codegen


@compiled
def borrowed_config(cfg):
    """The modal engine's configuration tuple (:func:`symimpact.forced.engine._modal_flight._pack`) with each
    of its arrays :func:`borrowed`; the caller keeps ``cfg`` alive."""
    return (borrowed(cfg[0]), borrowed(cfg[1]), cfg[2], borrowed(cfg[3]), cfg[4], cfg[5],
            cfg[6], borrowed(cfg[7]), cfg[8], cfg[9], borrowed(cfg[10]), borrowed(cfg[11]),
            cfg[12])  # fmt: skip
