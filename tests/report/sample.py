"""A small hand-built results dict with known numbers, for testing the report writer."""

import numpy as np


def _family(title, kind, records=(), figures=(), notes=(), errors=(), status="ok", reason=""):
    return {
        "title": title,
        "kind": kind,
        "status": status,
        "reason": reason,
        "records": list(records),
        "figures": list(figures),
        "notes": list(notes),
        "errors": list(errors),
    }


def _tight(seed, ratio, criterion="volume", variant="narrow", dim=2):
    metric = "trace_ratio" if criterion == "trace" else "volume_ratio"
    return {
        "family": "strip",
        "variant": variant,
        "dim": dim,
        "cond": 100.0,
        "seed": seed,
        "criterion": criterion,
        "metric": metric,
        "ratio": ratio,
        "reference": f"SDP {criterion}",
        "outside": 2 if seed == 11 else 0,
        "task_index": seed,
    }


def sample_results() -> dict:
    """Volume ratios 1.0, 1.5, 3.0 (worst seed 12); trace ratios 1.2, 1.1 and one refused SDP."""
    strip = [
        _tight(10, 1.0),
        _tight(11, 1.5, variant="wide", dim=3),
        _tight(12, 3.0),
        _tight(13, 1.2, criterion="trace"),
        _tight(14, 1.1, criterion="trace", variant="wide"),
        _tight(15, None, criterion="trace"),  # a refused SDP reference
    ]
    recursive = [
        {
            "family": "recursive",
            "variant": "width 0.2",
            "dim": dim,
            "seed": 20 + dim,
            "k": k,
            "criterion": "volume",
            "metric": "volume_ratio",
            "ratio": 1.0 + 0.1 * k * dim,
            "lower_ratio": 1.1 + 0.1 * k * dim,
            "reference": "SDP volume, all k strips",
            "task_index": dim,
        }
        for dim in (2, 3)
        for k in (1, 5)
    ]
    speed = [
        {"family": "speed", "name": "one call", "value": 4e-5, "unit": "s"},
        {
            "family": "speed",
            "name": "batch",
            "value": 2e-7,
            "unit": "s/update",
            "throughput": 5e6,
            "ratio": 200.0,
            "ratio_label": "speed-up vs one call",
        },
    ]
    figure = {
        "title": "narrow strip",
        "seed": 10,
        "ellipsoid": {"center": [0.0, 0.0], "shape": np.diag([4.0, 1.0]).tolist()},
        "strips": [{"a": [2.0, 0.0], "b": 0.0}],
        "bounds": [
            {"label": "analytic volume", "center": [0.0, 0.0], "shape": [[0.5, 0], [0, 1.5]]},
            {"label": "SDP volume optimum", "center": [0.0, 0.0], "shape": [[0.5, 0], [0, 1.5]]},
        ],
        "task_index": 0,
    }
    paper = {
        "family": "papers",
        "paper": "HS96",
        "script": "hs96_demo",
        "quick": True,
        "markdown": "## HS96 demo\n\n| quantity | paper | optbound |\n|---|---|---|\n| x | 1 | 2 |",
        "figures": ["papers/hs96_demo/demo.png"],
        "task_index": 0,
    }
    return {
        "schema": 1,
        "meta": {
            "suite": "quick",
            "seed": 0,
            "jobs": 2,
            "started": "2026-01-01T00:00:00+00:00",
            "wall_time_s": 12.5,
            "optbound": "0.1.0",
            "python": "3.11",
            "numpy": "2.4",
            "machine": "Linux x86_64",
            "processor": "Test CPU",
            "cpus": 2,
            "load_average": [1.25, 0.8, 0.5],
            "complete": True,
        },
        "families": {
            "strip": _family(
                "Strip family",
                "tightness",
                strip,
                [figure],
                errors=[{"task": {"seed": 99}, "error": "SolverError: inaccurate"}],
            ),
            "recursive": _family("Recursive family", "recursive", recursive),
            "speed": _family("Speed: analytic", "speed", speed, notes=["codac is not installed"]),
            "papers": _family("Papers", "papers", [paper]),
            "missing": _family("Missing family", "tightness", status="skipped", reason="needs x"),
        },
    }
