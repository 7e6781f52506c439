"""Benchmark reports: results.json/CSV, Markdown tables, PNG figures, the bench headline.

``write_report(results, out_dir)`` builds everything from the results dict that
``optbound bench`` saves, so ``optbound report DIR`` can rebuild a report from
``DIR/results.json`` alone.
"""

from optbound._lazy import attach
from optbound.report.document import REPORT_FILE, write_report
from optbound.report.headline import headline_rows
from optbound.report.readme import headline_refusal, source_readme, update_readme
from optbound.report.results import RESULTS_FILE, load_results, save_results, write_csv

__all__ = [
    "REPORT_FILE",
    "RESULTS_FILE",
    "headline_refusal",
    "headline_rows",
    "load_results",
    "save_results",
    "source_readme",
    "update_readme",
    "write_csv",
    "write_report",
]

__getattr__, __dir__ = attach(__name__, public=__all__, submodules=())
