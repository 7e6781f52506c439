"""Progress of a suite on stderr: one bar per family, and a total whose ETA weighs task cost.

Tasks differ in cost by orders of magnitude (a 4-D recursive task with 50 strips and lower
bounds against a 2-D strip fusion), so a count of finished tasks says little about the time
left. The total bar advances by each task's estimated cost (``Family.cost``); tqdm's rate,
and so its ETA, is then in cost per second, which calibrates the estimate as the run goes.

Bars redraw themselves with cursor movements, which only a terminal understands: into a file
or a pipe (a log, CI), one plain line per finished family is written instead.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

from tqdm import tqdm

_TOTAL_FORMAT = "{desc}: {percentage:3.0f}%|{bar}| [{elapsed}<{remaining}, cost-weighted]"
# No per-family ETA: with the longest tasks first, a family's tasks start at different times,
# so its own rate says nothing about the time left; only the total's cost-weighted ETA does.
_FAMILY_FORMAT = "{desc}: {percentage:3.0f}%|{bar}| {n_fmt}/{total_fmt}"


class Progress:
    """Bars for ``families`` (name -> list of task costs) on ``stream`` (default stderr).

    A no-op when not ``enabled``; when ``stream`` is not a terminal, one line per finished
    family instead of bars. Use it as a context manager: leaving it closes the bars.

    Parameters
    ----------
    title : str
        The total bar's label (the command that repeats the run).
    families : dict of str to list of float
        Family name -> the estimated costs of its tasks (``Family.cost``).
    enabled : bool
        Show anything at all.
    stream : file-like, optional
        Where to write (default ``sys.stderr``).
    """

    def __init__(
        self,
        title: str,
        families: dict[str, list[float]],
        enabled: bool = True,
        stream: TextIO | None = None,
    ):
        self.stream = stream or sys.stderr
        self.enabled = enabled and bool(families)
        self.bars_shown = self.enabled and self.stream.isatty()
        self.title, self.start = title, time.perf_counter()
        self.left = {name: len(costs) for name, costs in families.items()}
        if not self.bars_shown:
            return
        total = sum(sum(costs) for costs in families.values())
        self.total = tqdm(
            total=total, desc=title, bar_format=_TOTAL_FORMAT, position=0, file=self.stream
        )
        width = max(len(name) for name in families)
        self.bars = {
            name: tqdm(
                total=len(costs),
                desc=f"  {name:<{width}}",
                position=i + 1,
                bar_format=_FAMILY_FORMAT,
                file=self.stream,
            )
            for i, (name, costs) in enumerate(families.items())
        }

    def done(self, name: str, cost: float) -> None:
        """Record that one task of family ``name`` has finished.

        Parameters
        ----------
        name : str
            The task's family.
        cost : float
            The task's estimated cost, by which the total bar advances.
        """
        if not self.enabled:
            return
        self.left[name] -= 1
        if not self.bars_shown:
            if not self.left[name]:
                elapsed = time.perf_counter() - self.start
                print(f"{self.title}: {name} done ({elapsed:.1f} s)", file=self.stream)
            return
        self.bars[name].update()
        # Float costs summed in another order can overshoot the total by rounding, which
        # tqdm would show as a negative time left.
        self.total.update(min(cost, self.total.total - self.total.n))

    def close(self) -> None:
        """Close the bars (the cursor moves below them); nothing to do without bars."""
        if self.bars_shown:
            for bar in self.bars.values():
                bar.close()
            self.total.close()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
