"""Benchmarks behind ``knic bench``: each measures real components and prints its figures."""
