"""Outer ellipsoid of an ellipsoid intersected with a strip [HS96, eqs. (24)-(30)].

For ``E = {x : (x - c)^T C^{-1} (x - c) <= 1}`` and the strip ``S = {x : |a^T x - b| <= 1}``
[HS96, eq. (23)], every lambda >= 0 gives the ellipsoid [HS96, eq. (24)]

    eps = b - a^T c,   G = a^T C a,   u = 1 + lambda G,
    C0  = C - lambda C a a^T C / u,   centre = c + lambda eps C a / u,
    K   = 1 + lambda - lambda eps^2 / u,   shape = K C0,

which contains E ∩ S [HS96, eq. (25)]; so every result here is a guaranteed outer bound and the
criteria only choose *which* member. The four cases of [HS96, Fig. 1] compare the strip's
interval ``[b - 1, b + 1]`` for a^T x with the ellipsoid's ``[a^T c - sqrt(G), a^T c + sqrt(G)]``.

Conventions of this module (numerical decisions, all conservative):

- Guarantee: the result's floats, read exactly, contain E ∩ S. The member is evaluated in the
  local frame of E's centre with certified error bounds (``eps = b - a^T c``, ``C a`` and
  each entry of the shape in twice the working precision, the centre in midpoint-radius
  arithmetic) and inflated by a certified margin (``optbound.analytic._kernels.midrad``); ``margin``
  reports it. It is about ``U cond(result)`` (each shape entry is rounded once; storing the
  result as floats alone costs that much in its thin direction). Near-degenerate
  results are widened to the output domain (``optbound._core.domain``), never refused.
- ``clip=True`` first clips each plane to the ellipsoid's (outward) extent: a plane missing the
  ellipsoid moves to the tangent plane. This does not change E ∩ S but shrinks the result a lot
  in the partial case. A half-space is always clipped (its open side ends at E's extent).
- The strip used for fusion is never thinner than ``MIN_REL_WIDTH`` times the ellipsoid's
  extent along a (it is widened, which can only enlarge the bound); a plane that merely
  *touches* E gives a thin ellipsoid containing the touching point.
- "inconsistent" (no ellipsoid) is declared only when it is proven: even the outward-rounded
  strip misses the outward-rounded extent of E.
- If a chosen member cannot be certified (K not provably positive, output outside the domain),
  lambda falls back to 0: E itself, always an outer bound.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optbound._core import raise_for
from optbound._core import validate as v
from optbound.analytic._kernels import batch as _batch
from optbound.analytic._kernels import threads as _threads
from optbound.analytic._kernels.strip_kernel import (
    BAD_A,
    BAD_B,
    BAD_LAM,
    GIVEN,
    LAM_MAX,
    LAMG_MAX,
    MIN_REL_WIDTH,
    OUT_DTYPES,
    PROJECTION,
    ROBUST,
    ROBUST_PROJECTION,
    TRACE,
    VOLUME,
    fuse_range,
    fuse_single,
    workspace,
)
from optbound.analytic._kernels.threads import ellipsoid_outputs, run_sliced
from optbound.sets.ellipsoid import Ellipsoid
from optbound.sets.result import BoundResult
from optbound.sets.strip import Halfspace, Strip

CASES = ("no_reduction", "consistent", "partial", "inconsistent")
CRITERIA = ("volume", "trace", "projection", "robust")
__all__ = [
    "CASES",
    "LAMG_MAX",
    "LAM_MAX",
    "MIN_REL_WIDTH",
    "intersect_strip",
    "intersect_strip_batch",
]


@dataclass(frozen=True)
class StripFusion(BoundResult):
    """Result of :func:`intersect_strip`.

    As a ``BoundResult``: ``set`` is ``ellipsoid``, always certified.

    Attributes
    ----------
    ellipsoid : Ellipsoid or None
        Outer bound of E ∩ S; None when the sets are disjoint.
    lam : float
        The lambda of [HS96, eq. (24)] that was used (0 for "no_reduction"/"inconsistent").
    case : str
        One of ``CASES`` [HS96, Fig. 1].
    consistency : float
        Consistency measure [HS96, eq. (29)] in [0, 1]; 0 when inconsistent.
    margin : float
        Certified inflation of the float member, relative (``rho + mu / lambda_min``, see
        ``optbound.analytic._kernels.midrad``); 0 when E itself is returned.
    """

    set_attribute = "ellipsoid"
    certified = True

    ellipsoid: Ellipsoid | None
    lam: float
    case: str
    consistency: float
    margin: float = 0.0


@dataclass(frozen=True)
class StripFusionBatch:
    """Batched result of :func:`intersect_strip_batch`.

    ``centers`` (B, n) and ``shapes`` (B, n, n) are zero where ``empty`` (B,) is True;
    ``lam`` (B,), ``case`` (B,) integer codes into ``CASES``, ``consistency`` (B,),
    ``margin`` (B,) the certified relative inflation (as in :class:`StripFusion`).
    """

    centers: np.ndarray
    shapes: np.ndarray
    lam: np.ndarray
    case: np.ndarray
    consistency: np.ndarray
    empty: np.ndarray
    margin: np.ndarray | None = None


# ----------------------------------------------------------------------------- the core
_BAD = {
    BAD_A: "{a} must be finite and non-zero, with a norm in [1e-60, 1e60] (the supported domain)",
    BAD_B: "{b} must be finite with |b| <= 1e120 (the supported domain)",
    BAD_LAM: "lam must be finite and >= 0 (every lambda >= 0 gives an outer bound)",
}


def _raise(code: int, index: int, names: tuple[str, str, str, str], batched: bool) -> None:
    """The ``ValueError`` of a kernel error code, naming the argument (and the instance)."""
    where = f" (instance {index})" if batched else ""
    if code in _BAD:
        raise ValueError(_BAD[code].format(a=names[2], b=names[3]) + where)
    raise_for(code, names[0], names[1], where)


def _mode(criterion, dims, lam, n_batch, n):
    """Kernel mode, per-instance lambda array (a placeholder where the kernel chooses it) and
    the coordinates of the projection criteria (empty if unused)."""
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {CRITERIA}, got {criterion!r}")
    if n < 2:
        raise ValueError("strip fusion needs dimension >= 2 (in 1-D E ∩ S is an interval)")
    idx = _NO_DIMS if dims is None else v.dims_index("dims", dims, n).astype(np.int64, copy=False)
    if criterion == "projection" and dims is None:
        raise ValueError("dims is required for criterion='projection' (the subspace to project on)")
    if lam is not None:
        lam = _batch.per_instance("lam", lam, n_batch, ())
        if np.any(lam < 0):
            raise ValueError(
                f"lam must be >= 0 (every lambda >= 0 gives an outer bound), got {lam}"
            )
        return GIVEN, lam, idx
    if criterion == "robust":
        mode = ROBUST if dims is None else ROBUST_PROJECTION
    else:
        mode = {"volume": VOLUME, "trace": TRACE, "projection": PROJECTION}[criterion]
    return mode, _NO_LAMBDAS, idx


_NO_DIMS = np.zeros(0, np.int64)
_NO_DIMS.flags.writeable = False  # the array type of ``dims_index``: one compiled kernel
_NO_LAMBDAS = np.zeros(1)  # the kernel reads lambdas in the GIVEN mode only


def _check_robust(steepness, midpoint) -> tuple[float, float]:
    return v.finite_scalar("steepness", steepness), v.finite_scalar("midpoint", midpoint)


def intersect_strip(
    E: Ellipsoid,
    S: Strip | Halfspace,
    criterion: str = "volume",
    dims=None,
    lam: float | None = None,
    clip: bool = True,
    steepness: float = 10.0,
    midpoint: float = 0.5,
) -> StripFusion:
    """Outer ellipsoid of ``E ∩ S`` from the family [HS96, eq. (24)], guaranteed in floating point.

    Guarantee: the returned ellipsoid, its floats read as exact numbers, contains E ∩ S exactly
    (for every criterion and every lambda >= 0): the member is evaluated with certified error
    bounds and inflated by a certified margin (module docstring). ``ellipsoid`` is None only
    when E and S are *proven* disjoint.

    Parameters
    ----------
    E : Ellipsoid
        Prior (predicted) set, dimension n >= 2.
    S : Strip or Halfspace
        Measurement strip ``|a^T x - b| <= 1`` [HS96, eq. (23)], or a half-space
        ``a^T x <= b`` (fused as the strip between E's lower tangent plane and ``a^T x = b``).
    criterion : {"volume", "trace", "projection", "robust"}
        ``"volume"``: most positive root of [HS96, eq. (26)] with N = n (lambda = 0 if none;
        a positive root exists iff G > n (1 - eps^2)). ``"trace"``: minimizes tr(shape).
        ``"projection"``: minimizes the volume of the projection onto the coordinates ``dims``,
        [HS96, eqs. (27)-(28)]. ``"robust"``: ``lambda_opt / (1 + exp(-S (CM - M)))``
        [HS96, eq. (30)] with CM the consistency measure [HS96, eq. (29)] and lambda_opt the
        volume-optimal lambda (projection-optimal when ``dims`` is given).
    dims : sequence of int, optional
        Coordinate subspace; required for ``"projection"``.
    lam : float, optional
        Explicit lambda >= 0; overrides the criterion. It refers to the strip actually fused
        (the clipped one when ``clip=True``); ignored for "no_reduction" and "inconsistent";
        capped at ``LAM_MAX`` and at ``LAMG_MAX / G`` (the returned ``lam`` is the one used).
    clip : bool
        Clip the strip to E's extent first (see the module docstring).
    steepness, midpoint : float
        S and M of [HS96, eq. (30)] (paper values 10 and 0.5).

    Returns
    -------
    StripFusion
        ``ellipsoid`` (None if E and S are disjoint), ``lam``, ``case``, ``consistency``,
        ``margin`` (the certified inflation, relative to the float member).

    Raises
    ------
    TypeError
        ``E`` not an Ellipsoid, ``S`` neither a Strip nor a Halfspace.
    ValueError
        Dimension mismatch, unknown criterion, missing or invalid ``dims``, negative ``lam``.

    Notes
    -----
    The family is ``{x : (x - c)^T C^{-1} (x - c) + lam (a^T x - b)^2 <= 1 + lam}``, i.e. the
    ellipsoid with centre ``c + lam C a (b - a^T c) / (1 + lam a^T C a)`` and shape
    ``(1 + lam - lam (b - a^T c)^2 / (1 + lam a^T C a)) (C^{-1} + lam a a^T)^{-1}`` [HS96,
    eqs. (24)-(25)]; every lam >= 0 gives an outer bound of E ∩ S, the criterion picks one.

    References
    ----------
    .. [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
       on an angle measurement technique", IFAC, 1996.

    Examples
    --------
    >>> import numpy as np
    >>> from optbound import Ellipsoid, Strip, analytic
    >>> E = Ellipsoid(np.zeros(2), np.eye(2))
    >>> f = analytic.intersect_strip(E, Strip([2.0, 0.0], 0.0))  # |2 x1| <= 1
    >>> f.case
    'consistent'
    >>> np.round(np.diag(f.ellipsoid.shape), 6)  # unit disc ∩ {|x1| <= 0.5}: diag(0.5, 1.5)
    array([0.5, 1.5])
    """
    if not isinstance(E, Ellipsoid):
        raise TypeError(f"E must be an Ellipsoid, got {type(E).__name__}")
    if not isinstance(S, (Strip, Halfspace)):
        raise TypeError(f"S must be a Strip or a Halfspace, got {type(S).__name__}")
    if E.dim != S.dim:
        raise ValueError(f"E and S must have the same dimension, got {E.dim} and {S.dim}")
    mode, lams, idx = _mode(criterion, dims, lam, 1, E.dim)
    steep, midp = _check_robust(steepness, midpoint)
    halfspace = isinstance(S, Halfspace)
    c, C, L, valid, r = fuse_single(
        E.center, E.shape, S.a, S.b, halfspace, clip, mode, lams[0], idx, steep, midp,
        _threads.workspace(workspace, E.dim),
    )  # fmt: skip
    code, case, consistency, lam_used, empty, margin = r
    if code:
        _raise(code, 0, _NAMES_SINGLE, False)
    if empty:
        ellipsoid = None
    elif lam_used == 0.0:
        ellipsoid = E
    else:
        ellipsoid = Ellipsoid._from_kernel(c, C, L, valid)
    return StripFusion(ellipsoid, float(lam_used), CASES[case], float(consistency), float(margin))


_NAMES_SINGLE = ("E.center", "E.shape", "S.a", "S.b")
_NAMES_BATCH = ("centers", "shapes", "a", "b")


def intersect_strip_batch(
    centers,
    shapes,
    a,
    b,
    criterion: str = "volume",
    dims=None,
    lam=None,
    clip: bool = True,
    steepness: float = 10.0,
    midpoint: float = 0.5,
    halfspace: bool = False,
) -> StripFusionBatch:
    """Batched :func:`intersect_strip` over B instances: one compiled, parallel pass.

    Each instance is computed by the same kernel as :func:`intersect_strip`, so the results
    agree bitwise with single calls, and carry the same guarantee.

    Parameters
    ----------
    centers : array_like, shape (B, n)
    shapes : array_like, shape (B, n, n)
        Symmetric positive-definite shape matrices in the supported domain (the lower triangle
        defines the matrix; the upper one must agree up to rounding).
    a : array_like, shape (n,) or (B, n)
        Strip normals (shared or per instance), non-zero.
    b : float or array_like of shape (B,)
        Strip offsets.
    criterion, dims, clip, steepness, midpoint
        As in :func:`intersect_strip`.
    lam : float or array_like of shape (B,), optional
        Explicit lambdas >= 0.
    halfspace : bool
        Read each (a, b) as the half-space ``a^T x <= b`` instead of the strip.

    Returns
    -------
    StripFusionBatch
        The B results, as arrays.

    Raises
    ------
    ValueError
        As :func:`intersect_strip`, naming the first failing instance; or on mismatched shapes.
    """
    c = _batch.float_array("centers", centers, 2)
    C = _batch.float_array("shapes", shapes, 3)
    n_batch, n = c.shape
    if C.shape != (n_batch, n, n):
        raise ValueError(f"shapes must have shape {(n_batch, n, n)}, got {C.shape}")
    # Non-finite a and b are refused per instance by the kernel (BAD_A, BAD_B), with its index.
    a = _batch.per_instance("a", a, n_batch, (n,), finite=False)
    b = _batch.per_instance("b", b, n_batch, (), finite=False)
    mode, lams, idx = _mode(criterion, dims, lam, n_batch, n)
    steep, midp = _check_robust(steepness, midpoint)
    out = ellipsoid_outputs(n_batch, n, *OUT_DTYPES)

    def fuse(start: int, stop: int) -> int:
        ws = _threads.workspace(workspace, n)
        return fuse_range(c, C, a, b, halfspace, clip, mode, lams, idx, steep, midp, out, ws,
                          start, stop)  # fmt: skip

    out_c, out_C, code, case, cons, lam_used, empty, margin = out
    bad = [i for i in run_sliced(fuse, n_batch) if i >= 0]
    if bad:
        _raise(int(code[bad[0]]), bad[0], _NAMES_BATCH, True)
    return StripFusionBatch(out_c, out_C, lam_used, case, cons, empty, margin)
