"""optbound.report (in progress)."""
