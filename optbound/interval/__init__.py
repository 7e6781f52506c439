"""optbound.interval (in progress)."""
