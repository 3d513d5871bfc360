"""Checks: compare solver results with a scene's limits and give each an outcome."""
