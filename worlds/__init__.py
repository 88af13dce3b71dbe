"""The simulated ERL apartment and its world data.

Public interface: :mod:`worlds.api` (sensor readings, commands, the :class:`~worlds.api.SimulationAPI`
protocol, :func:`~worlds.api.load_world`) and :class:`worlds.simulation.Simulation`, which implements it on
pybullet (DIRECT mode). World data lives in ``worlds/erl_home/`` (``erl_home.yaml``, ``erl_home_paper.yaml``,
``scenarios/``); :mod:`worlds.loader` validates it, :mod:`worlds.render` draws its map.
"""
