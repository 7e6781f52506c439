"""Outer ellipsoids of the Minkowski sum of two ellipsoids: the Schweppe family [HS96, eq. (14)].

For any kappa in (0, 1), the ellipsoid with centre ``c1 + c2`` and shape
``C1 / (1 - kappa) + C2 / kappa`` contains E1 + E2 (Schweppe, 1973). The criteria choose kappa:

- ``"volume"``: the exact minimizer of det. With p = (1 - kappa) / kappa it is the unique root
  of ``h(p) = sum_i p (p + 1) / (l_i + p) - n`` (l_i the generalized eigenvalues of
  ``C1 v = l C2 v``), which is increasing in p and bracketed by ``[sqrt(min l), sqrt(max l)]``;
  solved by safeguarded Newton on a tridiagonal standard form, polished on ``C1 + p C2``
  (``optbound.analytic._kernels.minkowski_kernel``). For two summands this member is the
  minimum-volume ellipsoid among all outer ellipsoids (Durieu, Walter & Polyak 2001).
- ``"trace"``: ``kappa = sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2))`` (closed form).
- ``"size_xy_psi"``: the root of the cubic [HS96, eqs. (15)-(17)] for the size measure
  ``tr(proj_xy C) * tr(proj_psi C)``; ``dims = (planar, heading)`` selects the coordinates
  (default in 3-D: planar ``(0, 1)``, heading ``(2,)``, the pose ``(x, y, psi)`` of HS96).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound._core import check_ellipsoid, raise_for
from optbound._core import validate as v
from optbound.analytic._kernels import batch as _batch
from optbound.analytic._kernels.minkowski_kernel import (
    BAD_KAPPA,
    OUT_OF_DOMAIN,
    P_GIVEN,
    P_TRACE,
    P_VOLUME,
    P_XY_PSI,
    sum_range,
)
from optbound.analytic._kernels.threads import ellipsoid_outputs, run_sliced
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.result import BoundResult

CRITERIA = ("volume", "trace", "size_xy_psi")
DEFAULT_XY_PSI = ((0, 1), (2,))


@dataclass(frozen=True)
class MinkowskiResult(BoundResult):
    """Outer ellipsoid of E1 + E2 and the Schweppe parameter kappa that produced it.

    The shape is computed from p = (1 - kappa) / kappa, so it stays accurate even when the
    reported kappa rounds to 0 or 1 (summands differing in size by ~1e16 or more).
    As a ``BoundResult``: ``set`` is ``ellipsoid``, always certified.

    Parameters
    ----------
    ellipsoid : Ellipsoid
        The outer bound.
    kappa : float
        The Schweppe parameter [HS96, eq. (14)].
    margin : float, default 0.0
        The certified relative inflation of the float member.
    """

    set_attribute = "ellipsoid"
    certified = True

    ellipsoid: Ellipsoid
    kappa: float
    margin: float = 0.0


@dataclass(frozen=True)
class MinkowskiBatch:
    """Batched result of :func:`minkowski_sum_batch`.

    Parameters
    ----------
    centers : np.ndarray, shape (B, n)
        Centres of the outer bounds.
    shapes : np.ndarray, shape (B, n, n)
        Shapes of the outer bounds.
    kappa : np.ndarray, shape (B,)
        Schweppe parameters.
    margin : np.ndarray, shape (B,), optional
        Certified relative inflation of each float member.
    """

    centers: np.ndarray
    shapes: np.ndarray
    kappa: np.ndarray
    margin: np.ndarray | None = None


def _xy_psi_dims(dims, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Validate ``dims = (planar, heading)``: two disjoint coordinate lists."""
    if dims is None:
        if n != 3:
            raise ValueError(
                f"dims=(planar, heading) is required for criterion='size_xy_psi' when dim={n} "
                "(the default ((0, 1), (2,)) is for 3-D poses)"
            )
        dims = DEFAULT_XY_PSI
    if not isinstance(dims, (tuple, list)) or len(dims) != 2:
        raise ValueError(f"dims must be a pair (planar, heading) of coordinate lists, got {dims}")
    planar = v.dims_index("dims[0] (planar)", dims[0], n)
    heading = v.dims_index("dims[1] (heading)", dims[1], n)
    if set(planar.tolist()) & set(heading.tolist()):
        raise ValueError(f"planar and heading coordinates must be disjoint, got {dims}")
    return planar, heading


_NAMES_SINGLE = (("E1.center", "E1.shape"), ("E2.center", "E2.shape"))
_NAMES_BATCH = (("centers1", "shapes1"), ("centers2", "shapes2"))


def _raise(code: int, index: int, names, batched: bool) -> None:
    """The ``ValueError`` of a kernel error code, naming the argument (and the instance)."""
    where = f" (instance {index})" if batched else ""
    if code == BAD_KAPPA:
        raise ValueError("kappa must lie in the open interval (0, 1)" + where)
    if code == OUT_OF_DOMAIN:
        raise ValueError(
            "the sum leaves the supported domain (semi-axes up to 1e60, see "
            "optbound._core.domain)" + where
        )
    raise_for(code % 10, *names[code // 10], where)


def _mode(criterion: str, kappa, dims, n_batch: int, n: int):
    """Kernel mode, per-instance p = (1 - kappa) / kappa (zeros where the kernel solves) and
    the (planar, heading) coordinates of ``size_xy_psi`` (empty otherwise)."""
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    if kappa is not None:
        k = _batch.per_instance("kappa", kappa, n_batch, ())
        if np.any((k <= 0) | (k >= 1)):
            raise ValueError(f"kappa must lie in the open interval (0, 1), got {kappa}")
        return P_GIVEN, np.ascontiguousarray((1.0 - k) / k), _NO_DIMS, _NO_DIMS
    if criterion == "size_xy_psi":
        planar, heading = _xy_psi_dims(dims, n)
        return (
            P_XY_PSI,
            np.zeros(n_batch),
            *(d.astype(np.int64, copy=False) for d in (planar, heading)),
        )
    mode = P_VOLUME if criterion == "volume" else P_TRACE
    return mode, np.zeros(n_batch), _NO_DIMS, _NO_DIMS


_NO_DIMS = np.zeros(0, np.int64)
_NO_DIMS.flags.writeable = False  # the array type of ``dims_index``: one compiled kernel


def _read_only(arr: np.ndarray) -> np.ndarray:
    """A read-only view of ``arr``."""
    view = arr.view()
    view.flags.writeable = False
    return view


def minkowski_sum(
    E1: Ellipsoid, E2: Ellipsoid, criterion: str = "volume", kappa=None, dims=None
) -> MinkowskiResult:
    """Outer ellipsoid of the Minkowski sum ``E1 + E2`` [HS96, eq. (14)], guaranteed in floats.

    Guarantee: the returned ellipsoid, its floats read as exact numbers, contains E1 + E2
    exactly (for every criterion and every kappa in (0, 1)): the member is evaluated with
    certified error bounds and inflated by a certified margin (``analytic._kernels.midrad``);
    near-degenerate results are widened to the output domain (``optbound._core.domain``).

    Parameters
    ----------
    E1, E2 : Ellipsoid
        Summands of the same dimension.
    criterion : {"volume", "trace", "size_xy_psi"}
        Size measure minimized over kappa (see the module docstring).
    kappa : float, optional
        Explicit Schweppe parameter in (0, 1); overrides the criterion.
    dims : pair of coordinate lists, optional
        ``(planar, heading)`` for ``"size_xy_psi"`` [HS96, eq. (15)]; default ``((0, 1), (2,))``
        in 3-D, required otherwise.

    Returns
    -------
    MinkowskiResult
        ``ellipsoid`` contains E1 + E2; ``kappa`` is the value used; ``margin`` the certified
        relative inflation of the float member.

    Raises
    ------
    TypeError
        If E1 or E2 is not an Ellipsoid.
    ValueError
        On dimension mismatch, unknown criterion, kappa outside (0, 1), invalid dims, or a sum
        outside the supported domain.

    Notes
    -----
    Schweppe's family ``C(kappa) = C1 / (1 - kappa) + C2 / kappa``, centre ``c1 + c2``, contains
    E1 + E2 for every kappa in (0, 1) [HS96, eq. (14)]; the volume-optimal member is the
    minimum-volume ellipsoid containing the sum (Durieu, Walter & Polyak, 2001), the
    trace-optimal kappa is ``sqrt(tr C2) / (sqrt(tr C1) + sqrt(tr C2))``.

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound import Ellipsoid, analytic
    >>> E1 = Ellipsoid([0.0, 0.0], np.diag([4.0, 1.0]))
    >>> m = analytic.minkowski_sum(E1, Ellipsoid([0.0, 0.0], np.eye(2)))
    >>> print(round(m.kappa, 10))
    0.4191113192
    """
    for name, E in (("E1", E1), ("E2", E2)):
        if not isinstance(E, Ellipsoid):
            raise TypeError(f"{name} must be an Ellipsoid, got {type(E).__name__}")
    if E1.dim != E2.dim:
        raise ValueError(f"E1 and E2 must have the same dimension, got {E1.dim} and {E2.dim}")
    n = E1.dim
    mode, p, planar, heading = _mode(criterion, kappa, dims, 1, n)
    out = ellipsoid_outputs(1, n, np.int8, float, float)
    # A batch of one through the batch kernel (bitwise the same results); an Ellipsoid's
    # arrays are read-only, as the batch passes its inputs.
    inputs = (E1.center[None], E1.shape[None], E2.center[None], E2.shape[None])
    sum_range(*inputs, mode, p, planar, heading, out, 0, 1)
    (c,), (C,), (code,), (p_used,), (margin,) = out
    if code:
        _raise(int(code), 0, _NAMES_SINGLE, False)
    L = np.empty((n, n))
    E = Ellipsoid._from_kernel(c, C, L, check_ellipsoid(c, C, L))
    return MinkowskiResult(E, 1.0 / (1.0 + p_used), margin)


def minkowski_sum_batch(
    centers1, shapes1, centers2, shapes2, criterion: str = "volume", kappa=None, dims=None
) -> MinkowskiBatch:
    """Batched :func:`minkowski_sum` over B pairs: one compiled, parallel pass.

    Each pair is computed by the same kernel as :func:`minkowski_sum` (bitwise agreement, same
    guarantee).

    Parameters
    ----------
    centers1, centers2 : array_like, shape (B, n)
    shapes1, shapes2 : array_like, shape (B, n, n)
        Symmetric positive-definite shape matrices in the supported domain (the lower triangle
        defines the matrix; the upper one must agree up to rounding).
    criterion, dims
        As in :func:`minkowski_sum`.
    kappa : float or array_like of shape (B,), optional
        Explicit Schweppe parameters in (0, 1).

    Returns
    -------
    MinkowskiBatch
        The B outer bounds, their kappa and margins.

    Raises
    ------
    ValueError
        As :func:`minkowski_sum`, naming the first failing instance; or on mismatched shapes.
    """
    c1 = _batch.float_array("centers1", centers1, 2)
    C1 = _batch.float_array("shapes1", shapes1, 3)
    c2 = _batch.float_array("centers2", centers2, 2)
    C2 = _batch.float_array("shapes2", shapes2, 3)
    if c1.shape != c2.shape:
        raise ValueError(
            f"centers1 and centers2 must have the same shape, got {c1.shape}, {c2.shape}"
        )
    for name, C in (("shapes1", C1), ("shapes2", C2)):
        if C.shape != (*c1.shape, c1.shape[1]):
            raise ValueError(f"{name} must have shape {(*c1.shape, c1.shape[1])}, got {C.shape}")
    mode, p, planar, heading = _mode(criterion, kappa, dims, *c1.shape)
    n_batch, n = c1.shape
    out = ellipsoid_outputs(n_batch, n, np.int8, float, float)
    inputs = [_read_only(x) for x in (c1, C1, c2, C2)]  # the kernel's type (minkowski_sum)

    def add(start: int, stop: int) -> int:
        return sum_range(*inputs, mode, p, planar, heading, out, start, stop)

    out_c, out_C, code, p_used, margin = out
    bad = [i for i in run_sliced(add, n_batch) if i >= 0]
    if bad:
        _raise(int(code[bad[0]]), bad[0], _NAMES_BATCH, True)
    return MinkowskiBatch(out_c, out_C, 1.0 / (1.0 + p_used), margin)
