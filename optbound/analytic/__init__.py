"""optbound.analytic (in progress)."""
