"""``Evaluation``: the rows of :func:`optbound.evaluate` and their renderings.

Markdown (a table per run), JSON (floats written with ``repr``, so a counterexample read
back is the same float point), CSV, and a figure: the user's set over the exact paving and
the references for 2-D problems, and the ratio brackets over the suite.
"""

from __future__ import annotations

import csv
import io
import json
from typing import Any

import numpy as np

#: Keys of every row, in table order. ``size_*``: certified volume bracket of the returned set
#: (None for a set known only by ``contains``); ``exact_*``: the true set's
#: (:meth:`Problem.volume_bracket`); ``ratio_*``: ``[size_lo / exact_hi, size_hi / exact_lo]``,
#: and the same against each reference bound; ``soundness``: "proven" / "refuted" /
#: "undecided" (None on error rows); ``counterexample``: list of floats or None; ``method``:
#: how soundness was decided ("exact", "paving", "points"); ``seconds``: the estimator's call;
#: ``audit_seconds``: everything else for that problem (the exact paving and the references
#: are computed once per problem and shared by later estimators); ``error``: None or message.
COLUMNS = (
    "estimator",
    "family",
    "name",
    "seed",
    "dim",
    "size_lo",
    "size_hi",
    "exact_lo",
    "exact_hi",
    "ratio_lo",
    "ratio_hi",
    "ratio_optimal_ellipsoid_lo",
    "ratio_optimal_ellipsoid_hi",
    "ratio_best_box_lo",
    "ratio_best_box_hi",
    "soundness",
    "counterexample",
    "method",
    "seconds",
    "audit_seconds",
    "error",
)


class Evaluation:
    """The outcome of one estimator on a list of problems.

    Built by :func:`optbound.evaluate`; each argument is kept as the attribute of that name.

    Parameters
    ----------
    estimator : str
        The estimator's name.
    rows : list of dict
        One per problem, keys :data:`COLUMNS`. Numbers are None where they do not apply
        (error rows; sizes of sets known only by ``contains``).
    problems : list of Problem
        The problems, in the order of ``rows``.
    sets : list
        The set each call returned (None on error rows), for figures.
    """

    def __init__(self, estimator: str, rows: list[dict], problems: list, sets: list):
        self.estimator, self.rows, self.problems, self.sets = estimator, rows, problems, sets

    def __repr__(self) -> str:
        counts = self.counts()
        return f"Evaluation({self.estimator!r}, {len(self.rows)} rows, {counts})"

    def counts(self) -> dict[str, int]:
        """Count the rows per outcome.

        Returns
        -------
        dict of str to int
            Keys "proven", "refuted", "undecided" and "error", in that order.
        """
        out = dict.fromkeys(("proven", "refuted", "undecided", "error"), 0)
        for row in self.rows:
            out["error" if row["error"] else row["soundness"]] += 1
        return out

    # ------------------------------------------------------------------ renderings
    def to_markdown(self) -> str:
        """Render the rows as a Markdown table, one line per problem.

        Returns
        -------
        str
            The counts line, then the table (brackets as ``[lo, hi]``).
        """
        head = [
            "family",
            "problem",
            "size",
            "ratio to exact",
            "ratio to optimal ellipsoid",
            "ratio to best box",
            "soundness",
            "seconds",
        ]
        lines = [
            f"**{self.estimator}**: {self.counts()}",
            "",
            "| " + " | ".join(head) + " |",
            "|" + "---|" * len(head),
        ]
        for r in self.rows:
            if r["error"]:
                outcome = f"error: {r['error']}"
            elif r["soundness"] == "refuted":
                outcome = f"refuted at {_point(r['counterexample'])}"
            else:
                outcome = r["soundness"]
            cells = [
                r["family"],
                r["name"],
                _bracket(r["size_lo"], r["size_hi"]),
                _bracket(r["ratio_lo"], r["ratio_hi"]),
                _bracket(r["ratio_optimal_ellipsoid_lo"], r["ratio_optimal_ellipsoid_hi"]),
                _bracket(r["ratio_best_box_lo"], r["ratio_best_box_hi"]),
                outcome.replace("|", "\\|"),
                f"{r['seconds']:.2g}",
            ]
            lines.append("| " + " | ".join(str(c) for c in cells) + " |")
        return "\n".join(lines) + "\n"

    def to_json(self) -> str:
        """Render the rows as JSON.

        Returns
        -------
        str
            ``{"estimator": name, "rows": [...]}``, floats written with ``repr`` (a
            counterexample read back is the same float point), non-finite floats as null.
        """
        rows = [{k: _jsonable(r[k]) for k in COLUMNS} for r in self.rows]
        return json.dumps({"estimator": self.estimator, "rows": rows}, indent=1)

    def to_csv(self) -> str:
        """Render the rows as CSV.

        Returns
        -------
        str
            A header of :data:`COLUMNS`, then one line per row; a counterexample is a JSON
            list in its cell, None an empty cell.
        """
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        for r in self.rows:
            cells = {k: r[k] for k in COLUMNS}
            if cells["counterexample"] is not None:
                cells["counterexample"] = json.dumps(cells["counterexample"])
            writer.writerow({k: ("" if v is None else v) for k, v in cells.items()})
        return buf.getvalue()

    def figure(self, max_panels: int = 4):
        """Draw the 2-D problems and the ratio brackets with matplotlib.

        Parameters
        ----------
        max_panels : int, default 4
            At most this many 2-D problems are drawn (the exact paving, the references and
            the user's set, with any counterexample).

        Returns
        -------
        matplotlib.figure.Figure
            The problem panels, then the ratio brackets to the exact set over the suite (one
            segment per problem, log scale).
        """
        import matplotlib.pyplot as plt

        shown = [i for i, p in enumerate(self.problems) if p.dim == 2 and self.sets[i] is not None][
            :max_panels
        ]
        fig, axes = plt.subplots(1, len(shown) + 1, figsize=(4.2 * (len(shown) + 1), 4.0))
        axes = np.atleast_1d(axes)
        for ax, i in zip(axes, shown, strict=False):
            _draw_problem(ax, self.problems[i], self.sets[i], self.rows[i])
        _draw_brackets(axes[-1], self.rows)
        fig.suptitle(f"{self.estimator}: {self.counts()}")
        fig.tight_layout()
        return fig


def _bracket(lo, hi) -> str:
    if lo is None and hi is None:
        return "–"
    # One end None: a non-finite float read back from JSON (an unbounded size or ratio).
    return f"[{_end(lo, '?')}, {_end(hi, 'inf')}]"


def _end(value, missing: str) -> str:
    return missing if value is None else f"{value:.4g}"


def _point(x) -> str:
    return "(" + ", ".join(f"{c:.6g}" for c in x) + ")"


def _jsonable(value: Any) -> Any:
    if isinstance(value, float) and not np.isfinite(value):
        return None
    return value


def _draw_problem(ax, problem, S, row: dict) -> None:
    problem.exact().plot(ax=ax, show_outside=False)
    for (label, bound), style in zip(problem.references().items(), ("--", ":"), strict=True):
        _outline(ax, bound, label, style, "0.3")
    _outline(ax, S, "your set", "-", "C0")
    if row["counterexample"] is not None:
        ax.plot(*row["counterexample"], "kx", markersize=9, label="counterexample")
    ax.set_title(f"{problem.name}: {row['soundness']}", fontsize=9)
    ax.autoscale()
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7, loc="best")


def _outline(ax, S, label: str, style: str, color: str) -> None:
    """Draw a 2-D set: closed curves of optbound's types, a level contour of ``contains``."""
    from optbound.interval import Paving
    from optbound.sets import Box, Ellipsoid, PseudoEllipsoid

    if isinstance(S, Ellipsoid):
        ax.plot(*S.boundary().T, style, color=color, label=label)
    elif isinstance(S, Box):
        xs = [S.lo[0], S.hi[0], S.hi[0], S.lo[0], S.lo[0]]
        ys = [S.lo[1], S.lo[1], S.hi[1], S.hi[1], S.lo[1]]
        ax.plot(xs, ys, style, color=color, label=label)
    elif isinstance(S, PseudoEllipsoid):
        for k, line in enumerate(S.boundary()):
            ax.plot(*line.T, style, color=color, label=label if k == 0 else None)
    elif isinstance(S, Paving):
        hull = S.hull()
        if hull is not None:
            _outline(ax, hull, f"{label} (hull)", style, color)
    else:
        x0, x1 = ax.get_xlim()
        y0, y1 = ax.get_ylim()
        gx, gy = np.meshgrid(np.linspace(x0, x1, 200), np.linspace(y0, y1, 200))
        inside = np.asarray(S.contains(np.column_stack([gx.ravel(), gy.ravel()])))
        ax.contour(gx, gy, inside.reshape(gx.shape).astype(float), [0.5], colors=color)


def _draw_brackets(ax, rows: list[dict]) -> None:
    done = [r for r in rows if r["ratio_lo"] is not None]
    for k, r in enumerate(done):
        color = {"proven": "C2", "refuted": "C3"}.get(r["soundness"], "0.5")
        hi = r["ratio_hi"] if np.isfinite(r["ratio_hi"]) else 10 * max(r["ratio_lo"], 1.0)
        ax.plot([r["ratio_lo"], hi], [k, k], "-", color=color, linewidth=3)
        ax.plot([r["ratio_lo"], hi], [k, k], "|", color=color, markersize=8)  # narrow brackets
    ax.axvline(1.0, color="k", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("size / exact size (certified bracket)")
    ax.set_ylabel("problem")
    ax.set_title("ratio brackets (green proven, red refuted, grey undecided)", fontsize=9)
