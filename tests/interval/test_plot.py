"""2-D drawings of pavings and 2-D projections of 3-D ones."""

import matplotlib.pyplot as plt
import pytest

from optbound import interval as iv
from tests.interval.test_paving import _two_discs


def test_plots_2d_and_projection_of_3d():
    ax = _two_discs(0.1).plot()
    assert len(ax.collections) == 3  # outside, boundary, inner
    p3 = iv.sivia(lambda x, y, z: x**2 + y**2 + z**2, [[0.0, 1.0]], [[-1.5, 1.5]] * 3, 0.2)
    ax3 = p3.plot(dims=(0, 2))
    assert len(ax3.collections) == 2 and ax3.get_xlabel() == "x0" and ax3.get_ylabel() == "x2"
    with pytest.raises(ValueError, match="dims"):
        p3.plot(dims=(1, 1))
    plt.close("all")
