"""The GLH12 findings as verdicts computed from distributions over seeds.

[GLH12, Sect. 5] states its findings in words ("at least 7 robots are necessary to perform an
efficient localization", "over 9 robots the results are similar", "under 4 and over 8
obstacles" and "7 obstacles" fail); its Figs. 8-9 and the meaning of "efficient" are lost.
The rules below were fixed before the seeded sweeps were run and are stated in the report:

- a run is *efficient* when its final mean box area is at most ``EFFICIENT`` (the initial
  1 m² box: the team ends no worse than it started). A second reading, from the paper's own
  aim ("avoiding its drifting", Sect. 1): a run is *drift-free* when its mean box area over
  the last quarter of the run is at most ``DRIFT`` times the one over the second quarter;
- a configuration is *efficient* when at least ``MAJORITY`` of its runs are;
- each claim becomes ``reproduced``, ``partly`` or ``not reproduced`` by the functions
  here, from the fraction of efficient runs and the median final area per configuration;
  "over 9 robots the results are similar" is ``not applicable`` when neither count is
  efficient (two failing configurations are not the paper's plateau of good results).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

EFFICIENT = 1.0  # m²: final mean box area of an efficient run
MAJORITY = 0.5  # fraction of efficient runs that makes a configuration efficient
DRIFT = 1.2  # drift-free: last-quarter mean area <= DRIFT x second-quarter mean area
SIMILAR = 2.0  # "similar": medians within this factor
REPRODUCED, PARTLY, NOT_REPRODUCED = "reproduced", "partly", "not reproduced"
NOT_APPLICABLE = "not applicable: neither configuration is efficient"


def efficient_counts(fraction: Mapping[int, float]) -> set[int]:
    """The counts whose fraction of efficient runs is at least :data:`MAJORITY`."""
    return {n for n, f in fraction.items() if f >= MAJORITY}


def threshold_verdict(fraction: Mapping[int, float], threshold: int) -> str:
    """ "At least ``threshold`` are necessary": efficient exactly from ``threshold`` on.

    ``reproduced`` when the efficient counts run are exactly those ``>= threshold``;
    ``partly`` when some count is efficient and the efficient counts are upward closed (a
    threshold exists, at another count); ``not reproduced`` otherwise.
    """
    good = efficient_counts(fraction)
    if good == {n for n in fraction if n >= threshold} and good:
        return REPRODUCED
    if good and all(n in good for n in fraction if n >= min(good)):
        return PARTLY
    return NOT_REPRODUCED


def plateau_verdict(
    median: Mapping[int, float], fraction: Mapping[int, float], at: int, beyond: int
) -> str:
    """ "Over ``at`` the results are similar": no clear gain from ``at`` to ``beyond``.

    The paper's claim is that efficient tracking gains nothing beyond ``at`` robots, so it is
    :data:`NOT_APPLICABLE` when neither count is efficient. Otherwise two tests: the median
    final areas are within a factor :data:`SIMILAR`, and both counts are efficient.
    ``reproduced`` when both hold, ``partly`` when one does.
    """
    if fraction[at] < MAJORITY and fraction[beyond] < MAJORITY:
        return NOT_APPLICABLE
    near = max(median[at], median[beyond]) <= SIMILAR * min(median[at], median[beyond])
    same = (fraction[at] >= MAJORITY) == (fraction[beyond] >= MAJORITY)
    return REPRODUCED if near and same else PARTLY if near or same else NOT_REPRODUCED


def window_verdict(fraction: Mapping[int, float], works: Iterable[int]) -> str:
    """The counts that work are exactly ``works`` (among the counts run).

    ``reproduced`` when every count agrees, ``partly`` when more than half agree and some
    count is efficient, ``not reproduced`` otherwise (in particular when none is efficient:
    agreeing only on failures says nothing about where tracking works).
    """
    works = set(works)
    good = efficient_counts(fraction)
    agree = sum((n in good) == (n in works) for n in fraction)
    if agree == len(fraction):
        return REPRODUCED
    return PARTLY if good and agree > len(fraction) / 2 else NOT_REPRODUCED


def dip_verdict(fraction: Mapping[int, float], at: int, neighbours: Iterable[int]) -> str:
    """``at`` fails while its ``neighbours`` work.

    ``reproduced`` when the neighbours are efficient and ``at`` is not; ``partly`` when
    ``at`` has a smaller fraction of efficient runs than every neighbour (a dip, below the
    majority rule or not); ``not reproduced`` otherwise.
    """
    neighbours = list(neighbours)
    if fraction[at] < MAJORITY and all(fraction[n] >= MAJORITY for n in neighbours):
        return REPRODUCED
    if all(fraction[at] < fraction[n] for n in neighbours):
        return PARTLY
    return NOT_REPRODUCED


__all__ = [
    "DRIFT",
    "EFFICIENT",
    "MAJORITY",
    "NOT_APPLICABLE",
    "NOT_REPRODUCED",
    "PARTLY",
    "REPRODUCED",
    "SIMILAR",
    "dip_verdict",
    "efficient_counts",
    "plateau_verdict",
    "threshold_verdict",
    "window_verdict",
]
