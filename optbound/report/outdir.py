"""The report folder: checked (and created) before any work, never overwritten by accident."""

from __future__ import annotations

import tempfile
from pathlib import Path

#: Files whose presence marks a folder as holding a report of optbound bench or repro (or the
#: finished tasks of a run, :mod:`optbound.bench.run_folder`).
REPORT_MARKERS = ("results.json", "report.md", "run.json")


class OutDirError(ValueError):
    """The report folder cannot be used; the message is one line, for the command line."""


def prepare_out_dir(path: str | Path, force: bool = False) -> Path:
    """Create ``path`` if needed and check that a report can be written there.

    Parameters
    ----------
    path : str or Path
        The report folder.
    force : bool
        Allow a folder that already holds a report (its files are overwritten).

    Returns
    -------
    Path
        ``path``, which now exists and is writable.

    Raises
    ------
    OutDirError
        If ``path`` is a file, cannot be created or written, or already holds a report and
        ``force`` is false.
    """
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise OutDirError(f"--out {str(out)!r} exists and is not a directory")
    try:
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as exc:
        raise OutDirError(f"cannot write to --out {str(out)!r}: {exc.strerror or exc}") from None
    existing = [name for name in REPORT_MARKERS if (out / name).exists()]
    if existing and not force:
        resume = f", --resume {str(out)!r} to finish its run" if "run.json" in existing else ""
        raise OutDirError(
            f"--out {str(out)!r} already holds a report ({', '.join(existing)}); "
            f"pass --force to overwrite it{resume} or choose another --out"
        )
    return out
