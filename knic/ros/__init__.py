"""The ROS 2 adapter: KnIC and the simulated robot as ROS 2 nodes (rclpy, Fast DDS), at the edge.

Nothing in the core imports this package; it imports rclpy and the message packages of the ``ros`` extra
(``pip install -e '.[ros]'``). Its parts:

* :mod:`knic.ros.env` -- whether rclpy is installed and usable, one-line reasons when it is not;
* :mod:`knic.ros.topics` -- every topic name and QoS profile, in one table;
* :mod:`knic.ros.convert` and :mod:`knic.ros.camera` -- the conversions at the boundary, symmetric pairs
  (``pose_to_ros`` / ``pose_from_ros``, ``frame_to_ros`` / ``frame_from_ros``), each with a round-trip test;
* :mod:`knic.ros.knic_node` -- KnIC as a node: facts, fact events, plan, trace, pose, path, commands,
  octomaps and map out; goals and knowledge-base queries and updates in;
* :mod:`knic.ros.robot` -- :class:`~knic.ros.robot.RosRobot`, a :class:`core.robot.Robot` backed by ROS
  topics (KnIC's side of the robot seam across processes), and the clock that keeps KnIC on ``/clock``;
* :mod:`knic.ros.sim_node` -- the simulator as its own node: its sensors out, the robot's commands in;
* :mod:`knic.ros.split` -- KnIC assembled on a :class:`~knic.ros.robot.RosRobot` (``knic ros``).
"""
