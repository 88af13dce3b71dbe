"""Simulator internals: scene building (pybullet), navigation grid, camera, people, ground truth."""
