"""A run's folder while it runs: every finished task stored at once, so a run can be resumed.

A suite run that is interrupted (Ctrl-C, a killed process, a machine that goes down) keeps
every task it finished, and ``optbound bench --resume DIR`` runs only the others::

    DIR/run.json                       the command's arguments (what --resume repeats)
    DIR/tasks/<family>-<index>.json    one finished task: its family, index, task and result

A task is identified by its family and its index in ``family.tasks(suite, seed)``, which the
run's arguments determine. Each file is written under a temporary name, flushed to disk and
renamed (``os.replace`` is atomic on POSIX), so a process killed while writing leaves the
whole file or none. A stored result is used only if its task dict equals the one the family
gives now: a family whose tasks changed since redoes them.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

RUN_FILE = "run.json"
TASKS_DIR = "tasks"
FORMAT = 1


class RunFolderError(ValueError):
    """The folder is not a resumable run folder; the message is one line."""


class RunFolder:
    """The run folder ``path`` of a command called with ``arguments`` (a JSON-able dict).

    ``run.json`` is written with the first finished task, so a run that stops before any
    task finished leaves nothing behind.

    Parameters
    ----------
    path : str or Path
        The folder (created with the first finished task).
    arguments : dict
        The command's arguments, JSON-able, stored in ``run.json`` for ``--resume``.

    Examples
    --------
    >>> import tempfile
    >>> from optbound.bench.run_folder import RunFolder
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     folder = RunFolder(tmp, {"suite": "tiny", "seed": 0})
    ...     folder.save("strip", 0, {"seed": 7}, {"records": [{"ratio": 1.5}]})
    ...     resumed = RunFolder.open(tmp)
    ...     print(resumed.arguments)
    ...     print(resumed.load("strip", 0, {"seed": 7}), resumed.load("strip", 0, {"seed": 8}))
    {'suite': 'tiny', 'seed': 0}
    {'records': [{'ratio': 1.5}]} None
    """

    def __init__(self, path: str | Path, arguments: dict):
        self.path = Path(path)
        self.arguments = dict(arguments)
        self.tasks = self.path / TASKS_DIR
        self._started = (self.path / RUN_FILE).is_file()

    @classmethod
    def open(cls, path: str | Path) -> RunFolder:
        """The run folder at ``path``, with the arguments it was started with.

        Raises
        ------
        RunFolderError
            If ``path`` is not a directory or holds no readable ``run.json``.
        """
        path = Path(path)
        if not path.is_dir():
            raise RunFolderError(f"{str(path)!r} does not exist or is not a directory")
        try:
            stored = json.loads((path / RUN_FILE).read_text())
        except FileNotFoundError:
            raise RunFolderError(
                f"{str(path)!r} is not a run folder (it has no {RUN_FILE}; a run that "
                "finished no task leaves none)"
            ) from None
        except (OSError, json.JSONDecodeError) as exc:
            raise RunFolderError(f"cannot read {str(path / RUN_FILE)!r}: {exc}") from None
        if not isinstance(stored, dict) or stored.get("format") != FORMAT:
            raise RunFolderError(f"{str(path / RUN_FILE)!r} is not a run file of format {FORMAT}")
        return cls(path, stored["arguments"])

    def clear(self) -> None:
        """Forget the tasks stored by an earlier run (a fresh run into the same folder)."""
        for stored in self.tasks.glob("*.json") if self.tasks.is_dir() else ():
            stored.unlink()
        (self.path / RUN_FILE).unlink(missing_ok=True)
        self._started = False

    def load(self, family: str, index: int, task: dict) -> dict | None:
        """Read the stored result of task ``index`` of ``family``.

        Parameters
        ----------
        family : str
            The family's name.
        index : int
            The task's index in ``family.tasks(suite, seed)``.
        task : dict
            The task dict the family gives now; a result stored for another one is ignored.

        Returns
        -------
        dict or None
            The stored result, or None if the task is not finished (or was stored for another
            task dict).
        """
        try:
            stored = json.loads(self._file(family, index).read_text())
        except (FileNotFoundError, json.JSONDecodeError):
            return None
        return stored["result"] if stored.get("task") == _json_roundtrip(task) else None

    def save(self, family: str, index: int, task: dict, result: dict) -> None:
        """Store the result of task ``index`` of ``family`` (atomically).

        Parameters
        ----------
        family : str
            The family's name.
        index : int
            The task's index in ``family.tasks(suite, seed)``.
        task : dict
            The task dict (compared on :meth:`load`).
        result : dict
            The task's result, JSON-able.
        """
        if not self._started:
            self.tasks.mkdir(parents=True, exist_ok=True)
            _write_atomic(self.path / RUN_FILE, {"format": FORMAT, "arguments": self.arguments})
            self._started = True
        entry = {"family": family, "index": index, "task": task, "result": result}
        _write_atomic(self._file(family, index), entry)

    def _file(self, family: str, index: int) -> Path:
        return self.tasks / f"{family}-{index:04d}.json"


def _json_roundtrip(value):
    return json.loads(json.dumps(value))


def _write_atomic(path: Path, value: dict) -> None:
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with temporary.open("w") as fh:
        json.dump(value, fh, allow_nan=False)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(temporary, path)
