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


def _records(ratios, bound=None):
    extra = {"bound": bound} if bound else {}
    return [{"ratio": r, "variant": "v", **extra} for r in ratios]


def test_histogram_titles_say_what_the_bound_is_and_use_a_linear_axis_far_from_1():
    plt = figures.pyplot()
    fig, (far, near) = plt.subplots(1, 2)
    figures._gap_panel(far, _records([1.5, 2.0, 3.2], "optimal"), "optimal_pseudo_L4", "exact")
    figures._gap_panel(near, _records([1.0 + 1e-7, 1.002, 1.3]), "volume", "SDP volume")
    assert far.get_title() == "optimal optimal_pseudo_L4 vs exact" and far.get_xscale() == "linear"
    assert near.get_title() == "analytic volume vs SDP volume" and near.get_xscale() == "symlog"
    plt.close(fig)


def test_the_zoom_label_lies_inside_its_panel_clear_of_the_title():
    plt = figures.pyplot()
    fig, ax = plt.subplots(layout="constrained")
    figures._draw_instance(ax, _spec(0.05))
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (inset,) = ax.child_axes
    labels = [t for t in [inset.title, *inset.texts] if t.get_text() == "zoom on the exact set"]
    assert len(labels) == 1
    label = labels[0].get_window_extent(renderer)
    panel = ax.get_window_extent(renderer)
    assert panel.x0 <= label.x0 and label.x1 <= panel.x1
    assert panel.y0 <= label.y0 and label.y1 <= panel.y1
    assert not label.overlaps(ax.title.get_window_extent(renderer))
    plt.close(fig)
