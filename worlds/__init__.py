"""The simulated ERL apartment and its world data.

:class:`worlds.simulation.Simulation` is the robot of the robot seam (:class:`core.robot.Robot`: sensor
readings without ground truth, commands) and the referee's oracle (:class:`worlds.oracle.Oracle`: true poses,
frame truth, sound emitters, counters, true facts) on pybullet (DIRECT mode); :mod:`worlds.api` adds world
loading, the noise configuration and :class:`~worlds.api.SimulationAPI` (both protocols plus the simulator's
controls). World data lives in ``worlds/erl_home/`` (``erl_home.yaml``, ``erl_home_paper.yaml``,
``scenarios/``); :mod:`worlds.loader` validates it, :mod:`worlds.render` draws its map. The simulator's parts
are in :mod:`worlds.sim`: scene (rendering), robot (base controller), navigation (grid, planner), goals (where
symbolic goals end), hands (gripper and people's hands), items, people, perception (noisy detector), contacts,
events (scenario events), truth (true facts).
"""
