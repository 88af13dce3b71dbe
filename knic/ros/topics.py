"""Every topic and service of the adapter, with its message type and QoS, in one place (see the README).

Frames: ``map`` is the world frame of :mod:`core.robot` (metres, z up); the camera's optical frame is
``camera_optical``. Stamps are simulated seconds (``/clock``) in a simulated run, the robot's clock otherwise.

JSON payloads travel as ``std_msgs/String``; request/reply topics carry a correlation ``id`` chosen by the
requester and echoed in the reply.
"""

from __future__ import annotations

from typing import Any

MAP_FRAME = "map"
CAMERA_FRAME = "camera_optical"

# --------------------------------------------------------------------------- KnIC node (knic_node.py)
FACTS = "/knic/facts"  # String JSON snapshot, transient local
FACT_EVENTS = "/knic/fact_events"  # String JSON, one per knowledge-base change
PLAN = "/knic/plan"  # String JSON, the latest plan
TRACE = "/knic/trace"  # String JSON, one per trace event
GOAL = "/knic/goal"  # String: an English command or PDDL atoms
GOAL_REPLY = "/knic/goal_reply"  # String JSON: the intake's reply
QUESTION = "/knic/question"  # String JSON: the open confirmation question or its closing, transient local
ANSWER = "/knic/answer"  # String: the answer (JSON {id, text} or plain text)
KB_REQUEST = "/knic/kb/request"  # String JSON {id, op, ...}: query or update
KB_REPLY = "/knic/kb/reply"  # String JSON {id, ok, result | error}
KB_CLEAR_GOALS = "/knic/kb/clear_goals"  # std_srvs/Trigger
KB_PROBLEM = "/knic/kb/problem"  # std_srvs/Trigger: the PDDL problem in the response's message
OCTOMAP_PREFIX = "/knic/octomap/"  # + <kind>_<name>: visualization_msgs/MarkerArray
KNIC_MAP = "/knic/map"  # nav_msgs/OccupancyGrid, transient local
ROBOT_POSE = "/erlc/robot_pose"  # geometry_msgs/PoseStamped at 10 Hz
TRAJECTORY = "/erlc/trajectory"  # nav_msgs/Path on every (re)plan of the base
COMMAND_LOG = "/erlc/command"  # String JSON: every command KnIC sends to the robot

# ----------------------------------------------------------- the robot seam (sim_node.py / robot.py)
CLOCK = "/clock"  # rosgraph_msgs/Clock
TICK = "/sim/tick"  # String JSON manifest: what the simulator published for time t
STEP_UNTIL = "/knic/step_until"  # rosgraph_msgs/Clock: KnIC has done its work up to t (lockstep grant)
POSE_ESTIMATE = "/robot/pose_estimate"  # geometry_msgs/PoseStamped, localisation
ROBOT_STATE = "/robot/state"  # String JSON: navigation status, held item, camera pan
DEVICES = "/robot/devices"  # String JSON: device readings
SOUNDS = "/robot/sounds"  # String JSON per sound event
HEARD = "/robot/heard"  # String JSON per utterance heard
CAMERA_IMAGE = "/robot/camera/image"  # sensor_msgs/Image rgb8
CAMERA_DEPTH = "/robot/camera/depth"  # sensor_msgs/Image 32FC1 metres
CAMERA_MASKS = "/robot/camera/detections"  # sensor_msgs/Image mono8: the detections' masks stacked
CAMERA_LABELS = "/robot/camera/detection_labels"  # String JSON: label, confidence, identity per mask
CAMERA_INFO = "/robot/camera/camera_info"  # sensor_msgs/CameraInfo
CAMERA_POSE = "/robot/camera/pose"  # geometry_msgs/PoseStamped of the optical frame
ROBOT_MAP = "/map"  # nav_msgs/OccupancyGrid of the simulator, transient local
COMMAND = "/robot/command"  # String JSON {id, op, args}: a command to the robot
COMMAND_RESULT = "/robot/command_result"  # String JSON {id, ok, reason, value, state}


def reliable(depth: int = 10, *, latched: bool = False) -> Any:
    """A reliable QoS profile keeping the last ``depth`` messages; ``latched``: transient local (a late
    subscriber gets them)."""
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

    return QoSProfile(
        history=HistoryPolicy.KEEP_LAST,
        depth=depth,
        reliability=ReliabilityPolicy.RELIABLE,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE,
    )


def octomap_topic(kind: str, name: str) -> str:
    """``/knic/octomap/<kind>_<name>`` (the paper's ``people_jack``); unsafe characters become ``_``."""
    safe = "".join(ch if ch.isalnum() or ch == "_" else "_" for ch in f"{kind}_{name}")
    return OCTOMAP_PREFIX + safe
