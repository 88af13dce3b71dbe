"""The bottom layer every other package stands on: nothing here imports another KnIC package.

* :mod:`core.errors` -- the project's exception tree (one root, :class:`~core.errors.KnicError`).
* :mod:`core.robot` -- the robot seam: sensor readings without ground truth and the
  :class:`~core.robot.Robot` protocol every robot (the simulator, a ROS 2 adapter) implements.
"""
