"""Regenerate ``optbound/scenarios/_data/tank30.json`` from CORA's 30-state tank example.

Source: CORA (TUMcps/CORA on GitHub), commit ``6cb79424fc4085c1af10a13236bcca9776887683``,
file ``examples/contDynamics/linearSysDT/example_linearSysDT_observe_03_tank.m``, function
``aux_load_model`` (Althoff, *Guaranteed state estimation in CORA 2021*, ARCH 2021). That
function spells the model out as MATLAB literals (printed by CORA from
``tankModel_lin_dim30.mat``): ``A, B, c, C`` of ``linearSysDT``, ``params.R0, V, W`` as
``zonotope([center], [generators])``, the input ``params.u`` and the measurements
``params.y`` (stored, not simulated), ``dt``. This script parses those literals and writes them
unchanged (numbers as read, no arithmetic) as JSON; the MATLAB code is not translated.

Usage::

    git --git-dir=<CORA clone>/.git show <commit>:examples/contDynamics/linearSysDT/\\
        example_linearSysDT_observe_03_tank.m > tank03.m
    python benchmarks/convert_cora_tank.py tank03.m
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

COMMIT = "6cb79424fc4085c1af10a13236bcca9776887683"
SOURCE = "examples/contDynamics/linearSysDT/example_linearSysDT_observe_03_tank.m"
OUT = Path(__file__).resolve().parents[1] / "optbound" / "scenarios" / "_data" / "tank30.json"


def matrix(text: str) -> list[list[float]]:
    """A MATLAB matrix literal's body (rows split by ``;``, entries by blanks or commas)."""
    rows = [r for r in (row.replace(",", " ").split() for row in text.split(";")) if r]
    return [[float(x) for x in row] for row in rows]


def assignment(src: str, name: str) -> list[list[float]]:
    m = re.search(rf"^{name} = \[(.*?)\];", src, re.M | re.S)
    if m is None:
        raise ValueError(f"no assignment '{name} = [...]' in the CORA file")
    return matrix(m.group(1))


def zonotope(src: str, name: str) -> dict:
    m = re.search(rf"'{name}', zonotope\(\[(.*?)\], \[(.*?)\]\)", src, re.S)
    if m is None:
        raise ValueError(f"no field '{name}', zonotope(...) in the CORA file")
    return {"center": [row[0] for row in matrix(m.group(1))], "generators": matrix(m.group(2))}


def field(src: str, name: str) -> list[list[float]]:
    m = re.search(rf"'{name}', \[ \.\.\. % {name}\n(.*?)\n\s*\],? \.\.\.", src, re.S)
    if m is None:
        raise ValueError(f"no field '{name}', [ ... ] in the CORA file")
    # One row per line, ended by "; ... % u1" (a continuation and a comment).
    return matrix(re.sub(r"\.\.\.\s*%[^\n]*", "", m.group(1)))


def convert(src: str) -> dict:
    """The tank's data as a JSON-able dict (module docstring)."""
    dt = float(re.search(r"^dt = ([0-9.]+);", src, re.M).group(1))
    return {
        "source": f"TUMcps/CORA@{COMMIT}:{SOURCE} (aux_load_model)",
        "reference": "M. Althoff, Guaranteed state estimation in CORA 2021, ARCH 2021",
        "dt": dt,
        "A": assignment(src, "A"),
        "B": assignment(src, "B"),
        "c": [row[0] for row in assignment(src, "c")],
        "C": assignment(src, "C"),
        "R0": zonotope(src, "R0"),
        "W": zonotope(src, "W"),
        "V": zonotope(src, "V"),
        "u": field(src, "u"),
        "y": field(src, "y"),
    }


def main(path: str) -> None:
    data = convert(Path(path).read_text())
    OUT.write_text(json.dumps(data, separators=(",", ":")) + "\n")
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes)")


if __name__ == "__main__":
    main(sys.argv[1])
