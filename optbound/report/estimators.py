"""The report section "Your estimators": the rows ``optbound bench --estimator`` added."""

from __future__ import annotations

TITLE = "Your estimators"
NOTE = (
    "Each estimator of `--estimator` was run on the problems of this suite and seed "
    "(`optbound.problems.suite`, the instances of the families above) and audited by "
    "`optbound.evaluate`: a certified bracket of its set's volume, the ratio brackets to the "
    "exact set and to the references (the optimal ellipsoid and the best box the exact paving "
    "proves), and soundness: *proven* (exactly, or box by box on the exact paving), *refuted* "
    "at a point proven in the true set that the set excludes, or *undecided*. Rows: "
    "`results.json`, key `estimators`."
)


def estimators_section(results: dict) -> list[str]:
    """Render the section "Your estimators".

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves; its ``"estimators"`` entries hold
        the rows of :func:`optbound.evaluate` per estimator.

    Returns
    -------
    list of str
        Markdown parts: the title, :data:`NOTE` and one table per estimator; empty when the
        run had no ``--estimator``.
    """
    entries = results.get("estimators") or []
    if not entries:
        return []
    from optbound.problems.evaluation import Evaluation  # only for a run with estimators

    parts = [f"## {TITLE}", NOTE]
    for entry in entries:
        if not entry["rows"]:
            parts.append(f"**{entry['estimator']}**: no problem family in this run.")
            continue
        parts.append(Evaluation(entry["estimator"], entry["rows"], [], []).to_markdown())
    return parts
