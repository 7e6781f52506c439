"""Wall-clock timing: best-of-N means, calls batched by :meth:`timeit.Timer.autorange`."""

from __future__ import annotations

import statistics
import timeit
from collections.abc import Callable


def batch_times(fn: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> list[float]:
    """Time ``fn`` in ``repeat`` batches of back-to-back calls, each lasting >= ``min_time``.

    The batch size doubles from one call until a batch lasts ``min_time``; that batch is the
    first sample (it is a full batch), so the calibration costs no extra batch.

    Parameters
    ----------
    fn : callable
        The call to time, without arguments.
    repeat : int
        Number of batches (>= 1).
    min_time : float
        Minimum seconds per batch.

    Returns
    -------
    list of float
        Seconds per call of each batch.
    """
    timer = timeit.Timer(fn)
    number = 1
    while (first := timer.timeit(number)) < min_time:
        number *= 2
    return [t / number for t in (first, *timer.repeat(repeat - 1, number))]


def per_call(fn: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> float:
    """Time ``fn``: the best of ``repeat`` means over batches of >= ``min_time`` seconds.

    The minimum over repeats filters out interference from other processes; batching keeps
    timer resolution negligible for microsecond calls (:func:`batch_times`).

    Parameters
    ----------
    fn : callable
        The call to time, without arguments.
    repeat : int
        Number of batches; the fastest one counts.
    min_time : float
        Minimum seconds per batch (the batch size doubles until reached).

    Returns
    -------
    float
        Seconds per call.
    """
    return min(batch_times(fn, repeat, min_time))


def median_per_call(fn: Callable[[], object], repeat: int = 7, min_time: float = 0.05) -> float:
    """Time ``fn``: the median over ``repeat`` batches of >= ``min_time`` s (:func:`batch_times`).

    Parameters
    ----------
    fn : callable
        The call to time, without arguments.
    repeat : int
        Number of batches.
    min_time : float
        Minimum seconds per batch.

    Returns
    -------
    float
        Seconds per call.
    """
    return statistics.median(batch_times(fn, repeat, min_time))


def speed_record(family: str, name: str, seconds: float, unit: str = "s", **extra) -> dict:
    """Build one speed measurement record.

    Parameters
    ----------
    family : str
        The benchmark family's name.
    name : str
        What was timed.
    seconds : float
        The measured value (in ``unit``).
    unit : str
        The value's unit.
    **extra
        Further fields; ``ratio``/``ratio_label`` state what it is compared with.

    Returns
    -------
    dict
        ``{"family", "name", "value", "unit", **extra}``.

    Examples
    --------
    >>> from optbound.bench.timing import speed_record
    >>> record = speed_record("speed_demo", "one call", 2e-6, ratio=3.0, ratio_label="faster")
    >>> sorted(record)
    ['family', 'name', 'ratio', 'ratio_label', 'unit', 'value']
    >>> record["value"], record["unit"]
    (2e-06, 's')
    """
    return {"family": family, "name": name, "value": seconds, "unit": unit, **extra}
