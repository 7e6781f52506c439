"""Seeded random instances shared by the problem families (and the benchmark that runs them).

Every generator takes a numpy ``Generator``, so an instance is fully determined by the
instance seed recorded next to it (``np.random.default_rng(seed)``). The instance seeds of a
family come from :func:`task_seeds`, the suite seed and the family's name.
"""

from __future__ import annotations

import zlib

import numpy as np

from optbound.sets import Ellipsoid, Strip

# Strip position in the ellipsoid's own extent along the normal, u = (a^T x - a^T c) / h with
# h = sqrt(a^T C a), so u in [-1, 1] spans the ellipsoid. Each kind draws (lo, hi) in u.
STRIP_KINDS = ("narrow", "wide", "off-centre", "partial")


def task_seeds(seed: int, name: str, count: int) -> list[int]:
    """Draw reproducible 32-bit instance seeds for family ``name`` under suite seed ``seed``.

    The family name enters the seed sequence, so two families never share instances and
    adding a family does not change the instances of the others.

    Parameters
    ----------
    seed : int
        The suite seed (``optbound bench --seed``).
    name : str
        The family name.
    count : int
        How many seeds.

    Returns
    -------
    list of int
        ``count`` seeds in ``[0, 2**32)``.
    """
    state = np.random.SeedSequence([seed, zlib.crc32(name.encode())]).generate_state(count)
    return [int(s) for s in state]


def random_rotation(rng: np.random.Generator, dim: int) -> np.ndarray:
    """Draw a Haar-distributed orthogonal matrix (QR of a Gaussian matrix, signs fixed).

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    dim : int
        The matrix size.

    Returns
    -------
    np.ndarray, shape (dim, dim)
        An orthogonal matrix.
    """
    q, r = np.linalg.qr(rng.standard_normal((dim, dim)))
    return q * np.sign(np.diag(r))


def random_ellipsoid(
    rng: np.random.Generator, dim: int, cond: float, scale: float = 1.0
) -> Ellipsoid:
    """Draw a randomly rotated ellipsoid whose shape matrix has condition number ``cond``.

    The eigenvalues of the shape matrix are log-spaced from ``scale**2`` down to
    ``scale**2 / cond``, its eigenvectors a :func:`random_rotation`.

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    dim : int
        The dimension.
    cond : float
        Condition number of the shape matrix (>= 1).
    scale : float, default 1.0
        The largest semi-axis; the centre is standard normal times ``scale``.

    Returns
    -------
    Ellipsoid
        The random ellipsoid.
    """
    q = random_rotation(rng, dim)
    eig = scale**2 * np.logspace(0.0, -np.log10(cond), dim)
    shape = (q * eig) @ q.T
    return Ellipsoid(scale * rng.standard_normal(dim), 0.5 * (shape + shape.T))


def unit_direction(rng: np.random.Generator, dim: int) -> np.ndarray:
    """Draw a direction uniform on the unit sphere.

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    dim : int
        The dimension.

    Returns
    -------
    np.ndarray, shape (dim,)
        A unit vector.
    """
    d = rng.standard_normal(dim)
    return d / np.linalg.norm(d)


def strip_bounds(rng: np.random.Generator, kind: str) -> tuple[float, float]:
    """Draw strip limits (lo, hi) in the ellipsoid's normalised extent u in [-1, 1].

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    kind : {"narrow", "wide", "off-centre", "partial"}
        ``narrow``: width 0.05-0.3, near the centre. ``wide``: both planes cut, close to the
        rim. ``off-centre``: both planes cut, shifted by 0.4-0.8. ``partial``: only one plane
        cuts (the other lies beyond the ellipsoid), HS96's partial consistency [HS96, Sect. 4].

    Returns
    -------
    tuple of float
        ``(lo, hi)`` with ``lo < hi``, in units of the extent u.

    Raises
    ------
    ValueError
        For an unknown ``kind``.

    References
    ----------
    [HS96] U. D. Hanebeck, G. Schmidt, "Absolute localization of fast mobile robots based
    on an angle measurement technique", IFAC, 1996.
    """
    if kind == "narrow":
        width, mid = rng.uniform(0.05, 0.3), rng.uniform(-0.2, 0.2)
    elif kind == "wide":
        width, mid = rng.uniform(1.4, 1.8), rng.uniform(-0.05, 0.05)
    elif kind == "off-centre":
        width, mid = rng.uniform(0.2, 0.6), rng.choice([-1.0, 1.0]) * rng.uniform(0.4, 0.7)
    elif kind == "partial":
        lo = rng.uniform(-0.8, 0.6)
        return (lo, rng.uniform(1.2, 2.5)) if rng.random() < 0.5 else (-rng.uniform(1.2, 2.5), -lo)
    else:
        raise ValueError(f"kind must be one of {STRIP_KINDS}, got {kind!r}")
    return mid - 0.5 * width, mid + 0.5 * width


def strip_through(E: Ellipsoid, direction: np.ndarray, lo: float, hi: float) -> Strip:
    """Build the strip ``lo <= u <= hi`` in ``E``'s normalised extent along ``direction``.

    With ``h = sqrt(d^T C d)`` and ``m = d^T c`` for ``E = (c, C)``, the strip is
    ``m + h lo <= d^T x <= m + h hi``: u = -1 and u = 1 are the planes tangent to ``E``.

    Parameters
    ----------
    E : Ellipsoid
        The ellipsoid whose extent sets the scale.
    direction : np.ndarray, shape (n,)
        The strip's normal ``d``.
    lo, hi : float
        The limits in units of the extent u.

    Returns
    -------
    Strip
        The strip.
    """
    h = float(np.sqrt(direction @ E.shape @ direction))
    m = float(direction @ E.center)
    return Strip.from_bounds(direction, m + h * lo, m + h * hi)


def random_strip(rng: np.random.Generator, E: Ellipsoid, kind: str) -> Strip:
    """Draw a random strip of the given kind cutting ``E``.

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    E : Ellipsoid
        The ellipsoid the strip cuts.
    kind : {"narrow", "wide", "off-centre", "partial"}
        Where the strip lies (see :func:`strip_bounds`).

    Returns
    -------
    Strip
        A strip with a uniformly random normal.

    Raises
    ------
    ValueError
        For an unknown ``kind``.
    """
    direction = unit_direction(rng, E.dim)
    return strip_through(E, direction, *strip_bounds(rng, kind))


def strips_around(
    rng: np.random.Generator, E: Ellipsoid, point: np.ndarray, k: int, width: float
) -> list[Strip]:
    """Draw ``k`` random strips that all contain ``point``: a consistent measurement sequence.

    Each strip holds ``point`` at a uniformly random position across its width, like a
    bounded-error measurement of ``point``.

    Parameters
    ----------
    rng : np.random.Generator
        The instance's generator (``np.random.default_rng(seed)``).
    E : Ellipsoid
        The ellipsoid whose extent along each normal sets the strip's width.
    point : np.ndarray, shape (n,)
        The point every strip contains (the simulated true state).
    k : int
        The number of strips.
    width : float
        Normalised width of each strip (relative to ``E``'s extent along its normal).

    Returns
    -------
    list of Strip
        ``k`` strips, each with a uniformly random normal.
    """
    strips = []
    for _ in range(k):
        d = unit_direction(rng, E.dim)
        h = float(np.sqrt(d @ E.shape @ d))
        lo = float(d @ point) - rng.uniform(0.0, width) * h
        strips.append(Strip.from_bounds(d, lo, lo + width * h))
    return strips
