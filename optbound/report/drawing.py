"""The report's figures as a list of drawings, drawn one after another or over worker processes.

Writing the Markdown takes milliseconds; drawing the PNG figures takes seconds of matplotlib
layout and rasterising, after the suite's tasks have finished. The sections therefore only
*name* their figures (the file name is known before the figure exists) and queue the call
that draws it; :meth:`Drawings.draw` then runs the queue, over ``jobs`` forked processes when
there are several. Each drawing writes its own file from its own arguments, so the order and
the process a figure is drawn in change nothing in it.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path


class Drawings:
    """A queue of figure-drawing calls, each writing one PNG file.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> def draw(path, text):
    ...     path.write_text(text)
    ...     return path
    >>> with tempfile.TemporaryDirectory() as out:
    ...     drawings = Drawings()
    ...     name = drawings.add(draw, Path(out) / "a.png", text="png")
    ...     drawings.draw(jobs=1)
    ...     name, (Path(out) / "a.png").read_text()
    ('a.png', 'png')
    """

    def __init__(self) -> None:
        self.calls: list[tuple[Callable[..., Path], dict]] = []
        self.costs: list[float] = []

    def add(self, draw: Callable[..., Path], path: Path, cost: float = 1.0, **arguments) -> str:
        """Queue ``draw(path=path, **arguments)``.

        Parameters
        ----------
        draw : callable
            A function of :mod:`optbound.report.figures` that writes the figure to ``path``
            and returns it.
        path : Path
            The PNG file it writes.
        cost : float
            Its rough cost relative to the others: over several processes the costliest are
            drawn first, so that no long figure starts last.
        **arguments
            Its other arguments, by name.

        Returns
        -------
        str
            The file name the figure will have, for the Markdown that shows it.
        """
        self.calls.append((draw, {**arguments, "path": path}))
        self.costs.append(cost)
        return Path(path).name

    def draw(self, jobs: int = 1) -> None:
        """Draw every queued figure: in this process, or over ``jobs`` forked processes.

        Parameters
        ----------
        jobs : int
            Processes to draw in; more than one needs the ``fork`` start method (the children
            inherit the loaded matplotlib instead of importing it again), and falls back to
            drawing here without it.
        """
        from optbound.report.figures import pyplot

        pyplot()  # import once, before any fork
        workers = min(jobs, len(self.calls))
        if workers < 2 or "fork" not in multiprocessing.get_all_start_methods():
            for draw, arguments in self.calls:
                draw(**arguments)
            return
        order = sorted(range(len(self.calls)), key=lambda i: -self.costs[i])
        context = multiprocessing.get_context("fork")
        with ProcessPoolExecutor(workers, mp_context=context) as pool:
            futures = [pool.submit(self.calls[i][0], **self.calls[i][1]) for i in order]
            for future in futures:
                future.result()
