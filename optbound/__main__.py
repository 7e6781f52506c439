"""``python -m optbound`` is the ``optbound`` command (run from a source checkout's root, it
also finds the families of the repository's ``benchmarks/`` folder)."""

from optbound.cli import run

run()
