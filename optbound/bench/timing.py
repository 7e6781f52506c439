"""Wall-clock timing: best-of-N means, calls batched by :meth:`timeit.Timer.autorange`."""

from __future__ import annotations

import timeit
from collections.abc import Callable


def per_call(fn: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> float:
    """Time ``fn``: the best of ``repeat`` means over batches of >= ``min_time`` seconds.

    The minimum over repeats filters out interference from other processes; batching keeps
    timer resolution negligible for microsecond calls.

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
    timer = timeit.Timer(fn)
    number = 1
    while timer.timeit(number) < min_time:
        number *= 2
    return min(timer.repeat(repeat, number)) / number


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
