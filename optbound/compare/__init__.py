"""optbound.compare (in progress)."""
