"""Wall-clock timing: best-of-N means, calls batched by :meth:`timeit.Timer.autorange`."""

from __future__ import annotations

import timeit
from collections.abc import Callable


def per_call(fn: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> float:
    """Seconds per call of ``fn``: the best of ``repeat`` means over batches of >= ``min_time``.

    The minimum over repeats filters out interference from other processes; batching keeps
    timer resolution negligible for microsecond calls.
    """
    timer = timeit.Timer(fn)
    number = 1
    while timer.timeit(number) < min_time:
        number *= 2
    return min(timer.repeat(repeat, number)) / number


def speed_record(family: str, name: str, seconds: float, unit: str = "s", **extra) -> dict:
    """One speed measurement; ``ratio``/``ratio_label`` state what it is compared with."""
    return {"family": family, "name": name, "value": seconds, "unit": unit, **extra}
