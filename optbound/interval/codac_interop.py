"""Conversion between optbound's intervals, boxes and pavings and codac 2's objects.

Optional: needs ``pip install "optbound[codac]"`` (codac >= 2.0); codac is imported on the
first conversion. Bounds are float64 on both sides, so every conversion is exact (no
rounding, no widening). Empty intervals are ``[+inf, -inf]`` here and codac's empty interval
there.

=============================  =======================================================
optbound                       codac
=============================  =======================================================
``Interval`` of shape ()       ``codac.Interval``
``Interval`` of shape (n,)     ``codac.IntervalVector``
``Interval`` of shape (m, n)   list of m ``codac.IntervalVector``
``sets.Box``                   ``codac.IntervalVector`` (``to_codac`` only)
``Paving``                     ``{"inner", "bound", "outer_complem"}``: lists of
                               ``codac.IntervalVector`` (codac's paving is a bisection
                               tree with no public constructor from boxes)
``Paving`` (``from_codac``)    ``codac.PavingInOut``, e.g. the result of ``codac.sivia``
=============================  =======================================================

Importing codac sets the process's rounding mode to round-upward (its backend, gaol, relies
on it); optbound's interval code switches to round-to-nearest for its own work and restores
the mode afterwards (:mod:`optbound.interval.fenv`), so both libraries can be used side by
side.
"""

from __future__ import annotations

import numpy as np

from optbound._core import Box
from optbound.interval.interval import Interval, as_interval
from optbound.interval.paving import Paving

#: codac's names of the three box lists of a paving, and optbound's.
PAVING_PARTS = (("inner", "inner"), ("bound", "boundary"), ("outer_complem", "outside"))


def _codac():
    try:
        import codac
    except ImportError:
        raise ImportError('codac interop needs codac 2: pip install "optbound[codac]"') from None
    return codac


def _codac_interval(codac, lo: float, hi: float):
    return codac.Interval.empty() if lo > hi else codac.Interval(float(lo), float(hi))


def _codac_vector(codac, lo: np.ndarray, hi: np.ndarray):
    return codac.IntervalVector([_codac_interval(codac, a, b) for a, b in zip(lo, hi, strict=True)])


def to_codac(x):
    """Convert an ``Interval``, a ``Box`` or a ``Paving`` to its codac object (table above).

    Parameters
    ----------
    x : Interval, Box or Paving
        The optbound object.

    Returns
    -------
    codac.Interval, codac.IntervalVector, list or dict
        The codac object (see the module table).

    Raises
    ------
    ImportError
        If codac 2 is not installed.
    TypeError
        For any other type, or an ``Interval`` of more than two dimensions.
    """
    codac = _codac()
    if isinstance(x, Paving):
        return {
            theirs: [_codac_vector(codac, b[:, 0], b[:, 1]) for b in getattr(x, ours)]
            for theirs, ours in PAVING_PARTS
        }
    if isinstance(x, Box):
        return _codac_vector(codac, x.lo, x.hi)
    if not isinstance(x, Interval):
        raise TypeError(f"x must be an Interval, Box or Paving, got {type(x).__name__}")
    if x.ndim == 0:
        return _codac_interval(codac, float(x.lo), float(x.hi))
    if x.ndim == 1:
        return _codac_vector(codac, x.lo, x.hi)
    if x.ndim == 2:
        return [_codac_vector(codac, lo, hi) for lo, hi in zip(x.lo, x.hi, strict=True)]
    raise TypeError(f"x must have at most 2 dimensions to convert, got shape {x.shape}")


def _bounds(interval) -> tuple[float, float]:
    if interval.is_empty():
        return np.inf, -np.inf
    return interval.lb(), interval.ub()


def codac_boxes(vectors, n: int | None = None) -> np.ndarray:
    """Convert a list of ``codac.IntervalVector`` to an ``(m, n, 2)`` box array.

    Parameters
    ----------
    vectors : list of codac.IntervalVector
        The m boxes.
    n : int, optional
        The dimension, used only when the list is empty.

    Returns
    -------
    numpy.ndarray, shape (m, n, 2)
        Rows ``[lo, hi]``; ``[+inf, -inf]`` for empty intervals.
    """
    rows = [[_bounds(v[i]) for i in range(v.size())] for v in vectors]
    if not rows:
        return np.empty((0, n or 0, 2))
    return np.array(rows, dtype=float)


def from_codac(obj, eps: float | None = None):
    """Convert a codac ``Interval``, ``IntervalVector``, list of them or ``PavingInOut``.

    Parameters
    ----------
    obj
        The codac object.
    eps : float, optional
        For a paving: its bisection threshold (codac does not store it). Default: the
        widest side of its largest boundary box.

    Returns
    -------
    Interval or Paving
        An ``Interval`` of shape (), (n,) or (m, n), or a ``Paving``.

    Raises
    ------
    ImportError
        If codac 2 is not installed.
    TypeError
        For any other type.
    """
    codac = _codac()
    if isinstance(obj, codac.Interval):
        return _interval_of(np.array(_bounds(obj), dtype=float))
    if isinstance(obj, codac.IntervalVector):
        return as_interval(_interval_of(codac_boxes([obj])[0]))
    if isinstance(obj, list) and all(isinstance(v, codac.IntervalVector) for v in obj):
        return _interval_of(codac_boxes(obj))
    if isinstance(obj, codac.PavingInOut):
        return _paving_of(codac, obj, eps)
    raise TypeError(
        "obj must be a codac Interval, IntervalVector, list of IntervalVector or "
        f"PavingInOut, got {type(obj).__name__}"
    )


def _interval_of(boxes: np.ndarray) -> Interval:
    lo, hi = boxes[..., 0], boxes[..., 1]
    # Empty entries ([+inf, -inf]) are valid here but refused by the public constructor.
    return Interval._make(lo, hi, True) if np.any(lo > hi) else Interval(lo, hi)


def _paving_of(codac, paving, eps: float | None) -> Paving:
    parts = {
        ours: codac_boxes(paving.boxes(getattr(codac.PavingInOut, theirs)), paving.size())
        for theirs, ours in PAVING_PARTS
    }
    x0 = codac_boxes([paving.tree().hull()])[0]  # the root box
    if eps is None:
        bound = parts["boundary"]
        eps = float(np.max(bound[:, :, 1] - bound[:, :, 0])) if len(bound) else 0.0
    return Paving(parts["inner"], parts["boundary"], parts["outside"], Box(x0[:, 0], x0[:, 1]), eps)
