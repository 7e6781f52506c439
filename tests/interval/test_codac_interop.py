"""codac interop and optbound after ``import codac``, each in a child process.

Importing codac sets round-upward for the whole process, so these tests never import it in
the pytest process: a child imports codac *first*, then runs optbound, and prints JSON that
is compared here with the same computation in this (round-to-nearest) process.
"""

import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from optbound import interval as iv

# Not importorskip, which would import codac here and switch this process to round-upward.
pytestmark = pytest.mark.skipif(importlib.util.find_spec("codac") is None, reason="no codac")

ROOT = Path(__file__).resolve().parents[2]

PAVE = """
import json, numpy as np
from optbound import interval as iv
from optbound.interval.fenv import get_rounding
mode = get_rounding()
p = iv.sivia(lambda x, y: (x**2 + y**2, 2 * x**2 + y**2), [[-np.inf, 1], [1, np.inf]],
             [[-2.5, 2.5], [-2, 2]], eps=0.02)
third = iv.Interval(1.0) / iv.Interval(3.0)
"""


def _child(code: str) -> dict:
    prelude = "import codac  # first: sets round-upward process-wide\n"
    out = subprocess.run(
        [sys.executable, "-c", prelude + code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_optbound_computes_the_same_after_import_codac_and_restores_the_mode():
    got = _child(
        PAVE + "print(json.dumps({'mode': mode, 'after': get_rounding(),"
        "'inner': p.inner.tolist(), 'boundary': p.boundary.tolist(),"
        "'third': [float(third.lo), float(third.hi)],"
        "'up': bool((np.ones(1) + np.full(1, 2.0**-60) > 1.0)[0])}))"
    )
    assert got["up"], "codac no longer sets round-upward: this test would be vacuous"
    assert got["mode"] != 0 and got["after"] == got["mode"]
    p = iv.sivia(
        lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),
        [[-np.inf, 1], [1, np.inf]],
        [[-2.5, 2.5], [-2, 2]],
        eps=0.02,
    )
    assert got["inner"] == p.inner.tolist() and got["boundary"] == p.boundary.tolist()
    third = iv.Interval(1.0) / iv.Interval(3.0)
    assert got["third"] == [float(third.lo), float(third.hi)]


def test_round_trips_through_codac_are_exact():
    got = _child(
        PAVE
        + """
import codac
from optbound.interval.codac_interop import from_codac, to_codac
from optbound.sets import Box
back = from_codac(to_codac(iv.Interval([0.1, -np.inf], [0.2, 3.0])))  # finite, unbounded
empty = from_codac(to_codac(iv.Interval.empty((2,))))
empty_scalar = from_codac(to_codac(iv.Interval.empty()))
box = from_codac(to_codac(Box([0.0, 1.0], [2.0, 3.0])))
rows = from_codac(to_codac(iv.Interval([[0.0, 1.0], [2.0, 3.0]], [[0.5, 1.5], [2.5, 3.5]])))
scalar = from_codac(to_codac(iv.Interval(0.1, 0.3)))
parts = to_codac(p)
theirs = codac.sivia(codac.IntervalVector([[-2.5, 2.5], [-2, 2]]),
    codac.AnalyticFunction([v := codac.VectorVar(2)], codac.sqr(v[0]) + codac.sqr(v[1])),
    codac.Interval(0, 1), 0.1)
q = from_codac(theirs)
print(json.dumps({
  'lo': back.lo.tolist(), 'hi': back.hi.tolist(),
  'empty': [empty.is_empty.tolist(), bool(empty_scalar.is_empty)],
  'box': [box.lo.tolist(), box.hi.tolist()],
  'rows': [rows.lo.tolist(), rows.hi.tolist()], 'scalar': [float(scalar.lo), float(scalar.hi)],
  'sizes': {k: len(v) for k, v in parts.items()},
  'first_inner': [[parts['inner'][0][i].lb(), parts['inner'][0][i].ub()] for i in range(2)],
  'q': [q.X0.lo.tolist(), q.X0.hi.tolist(), q.eps, q.volume_bounds(), q.dim],
}))
"""
    )
    assert got["lo"] == [0.1, -np.inf] and got["hi"] == [0.2, 3.0]
    assert got["empty"] == [[True, True], True]  # empty stays empty
    assert got["box"] == [[0.0, 1.0], [2.0, 3.0]]
    assert got["rows"] == [[[0.0, 1.0], [2.0, 3.0]], [[0.5, 1.5], [2.5, 3.5]]]
    assert got["scalar"] == [0.1, 0.3]
    p = iv.sivia(
        lambda x, y: (x**2 + y**2, 2 * x**2 + y**2),
        [[-np.inf, 1], [1, np.inf]],
        [[-2.5, 2.5], [-2, 2]],
        eps=0.02,
    )
    assert got["sizes"] == {
        "inner": len(p.inner),
        "bound": len(p.boundary),
        "outer_complem": len(p.outside),
    }
    assert got["first_inner"] == p.inner[0].tolist()
    x0_lo, x0_hi, eps, (v_in, v_out), dim = got["q"]
    assert (x0_lo, x0_hi, dim) == ([-2.5, -2.0], [2.5, 2.0], 2)
    assert 0 < eps <= 0.1
    assert v_in <= np.pi <= v_out  # codac's paving of the unit disc, read back


def test_conversion_refuses_other_types():
    got = _child(
        """
import json
from optbound.interval.codac_interop import from_codac, to_codac
errors = []
for fn, arg in ((to_codac, 1.0), (from_codac, "x")):
    try:
        fn(arg)
    except TypeError as exc:
        errors.append(str(exc))
print(json.dumps(errors))
"""
    )
    assert "must be an Interval, Box or Paving, got float" in got[0]
    assert "must be a codac Interval" in got[1]
