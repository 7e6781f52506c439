"""Reading and writing the benchmark results: ``results.json`` (the source of truth) and CSV."""

from __future__ import annotations

import base64
import csv
import json
from pathlib import Path

RESULTS_FILE = "results.json"
SCHEMA = 1
# Leading CSV columns, in this order; any other record keys follow alphabetically.
CSV_FIRST = ("family", "variant", "dim", "cond", "k", "seed", "criterion", "metric", "ratio")


def save_results(results: dict, out_dir: str | Path) -> Path:
    """Write ``results`` to ``out_dir/results.json`` (strict JSON: no NaN or infinity).

    A family's ``attachments`` (``{relative path: base64 bytes}``, e.g. the figures of the
    papers' scripts) are written as files under ``out_dir``; the JSON keeps their names.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`load_results`).
    out_dir : str or Path
        The output directory, created if needed.

    Returns
    -------
    Path
        The path of ``results.json``.

    Raises
    ------
    ValueError
        If ``results`` holds a NaN or infinite float (strict JSON).

    Examples
    --------
    >>> import tempfile
    >>> from optbound.report import load_results, save_results
    >>> results = {"schema": 1, "meta": {"suite": "tiny"}, "families": {}}
    >>> with tempfile.TemporaryDirectory() as out:
    ...     path = save_results(results, out)
    ...     load_results(out) == results, path.name
    (True, 'results.json')
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    families = {}
    for name, fam in results["families"].items():
        for rel, data in fam.get("attachments", {}).items():
            target = out / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(base64.b64decode(data))
        # The JSON keeps the attachments' names only (the report links them).
        families[name] = fam
        if "attachments" in fam:
            families[name] = {**fam, "attachments": sorted(fam["attachments"])}
    path = out / RESULTS_FILE
    text = json.dumps({**results, "families": families}, indent=1, allow_nan=False)
    path.write_text(text + "\n")
    return path


def load_results(directory: str | Path) -> dict:
    """Load ``directory/results.json`` written by ``optbound bench``.

    Parameters
    ----------
    directory : str or Path
        The output directory of a run.

    Returns
    -------
    dict
        The results, with their ``"schema"``, ``"meta"`` and ``"families"``.

    Raises
    ------
    ValueError
        If ``directory`` is not a directory, holds no results.json, or the file is not a
        results file of this schema.
    """
    directory = Path(directory)
    if not directory.is_dir():
        raise ValueError(f"directory {str(directory)!r} does not exist or is not a directory")
    path = directory / RESULTS_FILE
    if not path.is_file():
        raise ValueError(f"directory {str(directory)!r} has no {RESULTS_FILE} (run optbound bench)")
    try:
        results = json.loads(path.read_text())
    except json.JSONDecodeError as exc:
        raise ValueError(f"{path} is not valid JSON: {exc}") from None
    if not isinstance(results, dict) or results.get("schema") != SCHEMA:
        raise ValueError(f"{path} is not an optbound results file of schema {SCHEMA}")
    for key in ("meta", "families"):
        if not isinstance(results.get(key), dict):
            raise ValueError(f"{path} lacks the {key!r} section")
    return results


def records_of(results: dict, kinds: tuple[str, ...]) -> list[dict]:
    """Collect the records of the families whose kind is in ``kinds``, in report order.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`load_results`).
    kinds : tuple of str
        Family kinds, e.g. ``("tightness", "recursive")``.

    Returns
    -------
    list of dict
        The records, family by family.
    """
    return [
        rec
        for fam in results["families"].values()
        if fam["kind"] in kinds
        for rec in fam["records"]
    ]


def write_csv(results: dict, out_dir: str | Path) -> list[Path]:
    """Write the records as CSV sheets, one row per record.

    ``tightness.csv`` (tightness and recursive records), ``speed.csv`` and
    ``estimation.csv`` (observers of linear systems, per step); a sheet without records is
    not written. Columns: :data:`CSV_FIRST` present, then the other keys alphabetically.

    Parameters
    ----------
    results : dict
        The results dict that ``optbound bench`` saves (:func:`load_results`).
    out_dir : str or Path
        An existing output directory.

    Returns
    -------
    list of Path
        The files written.
    """
    written = []
    sheets = (
        ("tightness", ("tightness", "recursive")),
        ("speed", ("speed",)),
        ("estimation", ("estimation",)),
    )
    for name, kinds in sheets:
        rows = records_of(results, kinds)
        if not rows:
            continue
        keys = {key for row in rows for key in row}
        columns = [c for c in CSV_FIRST if c in keys] + sorted(keys - set(CSV_FIRST))
        path = Path(out_dir) / f"{name}.csv"
        with path.open("w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=columns)
            writer.writeheader()
            writer.writerows(rows)
        written.append(path)
    return written
