"""The worked example of ``docs/extending.md`` runs as written: a set type defined outside the
library plugs into the SDP layer, and its bound contains the set exactly."""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from optbound import Ellipsoid, Strip
from optbound.optimal import outer_ellipsoid

GUIDE = Path(__file__).resolve().parents[1] / "docs" / "extending.md"


def _ball_class():
    blocks = re.findall(r"```python\n(.*?)```", GUIDE.read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 1, "the guide has one worked example"
    namespace: dict = {}
    exec(compile(blocks[0], str(GUIDE), "exec"), namespace)
    return namespace["Ball"]


def test_the_guides_ball_works_with_the_sdp_layer():
    Ball = _ball_class()
    with pytest.raises(ValueError, match="radius"):
        Ball([0.0, 0.0], -1.0)
    ball = Ball([0.5, -0.25], 2.0)
    assert ball.contains([0.5, 1.75]) and not ball.contains([0.5, 1.8])
    assert ball.extent([1.0, 0.0]) == (-1.5, 2.5)
    strip = Strip.from_bounds([0.0, 1.0], -1.0, 0.5)
    r = outer_ellipsoid([ball, strip])
    ref = outer_ellipsoid([Ellipsoid([0.5, -0.25], 4.0 * np.eye(2)), strip])
    assert r.certified and r.objective == pytest.approx(ref.objective, rel=1e-9)
    # Corners of ball ∩ strip, as floats exactly in the set (nudged inward until the
    # rational check passes), must lie in the bound exactly: levels in rational arithmetic.
    (a, b), (_, d) = [[Fraction(float(x)) for x in row] for row in r.ellipsoid.shape]
    c = [Fraction(float(x)) for x in r.ellipsoid.center]
    for y in (-1.0, 0.5):
        half = np.sqrt(4.0 - (y + 0.25) ** 2)
        for x in (0.5 - half, 0.5 + half):
            while (Fraction(x) - Fraction(1, 2)) ** 2 + (Fraction(y) + Fraction(1, 4)) ** 2 > 4:
                x = np.nextafter(x, 0.5)
            u, w = Fraction(x) - c[0], Fraction(y) - c[1]
            assert (d * u * u - 2 * b * u * w + a * w * w) / (a * d - b * b) <= 1
