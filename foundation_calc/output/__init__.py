"""Output: rich tables for people on stdout, JSON for scripts, messages on stderr."""
