"""optbound.optimal (in progress)."""
