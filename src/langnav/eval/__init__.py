"""Evaluation: the paper's metrics and the map-analysis benchmarks."""
