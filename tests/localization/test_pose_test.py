"""landmarks.pose_test is the test pose_paving paves: same boxes, sound on points."""

import numpy as np

from optbound.compare.tri import point_test
from optbound.interval import Tri, pave
from optbound.localization.landmarks import pose_paving, pose_test
from optbound.problems import hs96_pose


def test_pose_test_paves_like_pose_paving():
    inst = hs96_pose.instance(5, 5, np.radians(0.5))
    args = (inst["landmarks"], inst["alphas"], np.radians(0.5), inst["landmark_shapes"])
    X0 = pose_paving(*args).hull()
    eps = float(np.max(X0.widths)) / 20
    theirs = pose_paving(*args, X0=X0, eps=eps)
    ours = pave(pose_test(*args, psi_range=(X0.lo[2], X0.hi[2])), X0, eps)
    assert np.array_equal(ours.inner, theirs.inner)
    assert np.array_equal(ours.boundary, theirs.boundary)
    truth = inst["truth"].copy()
    truth[2] -= 2 * np.pi * round((truth[2] - X0.center[2]) / (2 * np.pi))
    assert point_test(pose_test(*args), truth[None])[0] != Tri.FALSE
