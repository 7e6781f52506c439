"""The three estimators of issue 20's "Done when", as a user would write them."""

from optbound import Box


def hull_box(p):
    """The hull of the exact paving: sound by construction."""
    return p.exact().hull()


def shrunk_box(p):
    """The hull shrunk to 70 % about its centre: misses part of the set."""
    hull = p.exact().hull()
    half = 0.35 * hull.widths
    return Box(hull.center - half, hull.center + half)


def prior_ellipsoid(p):
    """The prior ellipsoid of a strip problem: contains E ∩ S."""
    return p.data["ellipsoid"]
