"""Figure styles: every reference drawn differently, labelled axes, zoom on a small exact set."""

import numpy as np

from optbound.report import figures


def test_each_sdp_reference_has_its_own_style():
    labels = ["SDP volume optimum", "SDP trace optimum", "SDP projection optimum", "SDP batch"]
    styles = [figures._style(label) for label in labels]
    keys = {(s["color"], str(s["ls"])) for s in styles}
    assert len(keys) == len(labels)
    assert figures._style("analytic volume")["color"] != figures._style("analytic trace")["color"]


def _spec(width):
    return {
        "title": "t",
        "seed": 1,
        "ellipsoid": {"center": [0.0, 0.0], "shape": np.eye(2).tolist()},
        "strips": [{"a": [1.0 / width, 0.0], "b": 0.0}, {"a": [0.0, 1.0 / width], "b": 0.0}],
        "bounds": [{"label": "SDP volume optimum", "center": [0, 0], "shape": np.eye(2).tolist()}],
    }


def test_panels_have_axis_labels_and_zoom_on_a_small_exact_set():
    plt = figures.pyplot()
    for width, zoomed in ((0.05, True), (0.8, False)):
        fig, ax = plt.subplots()
        figures._draw_instance(ax, _spec(width))
        assert ax.get_xlabel() and ax.get_ylabel()
        assert (len(ax.child_axes) == 1) == zoomed
        plt.close(fig)
