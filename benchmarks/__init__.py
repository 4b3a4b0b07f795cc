"""Benchmarks that print figures and ratios (run from the checkout: ``python -m benchmarks``)."""
