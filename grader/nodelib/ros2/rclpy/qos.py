"""rclpy.qos: QoSProfile, the policy enums and the predefined profiles with rmw's values."""
from __future__ import annotations

import warnings
from enum import Enum, IntEnum

import rosgrade_qos

from .duration import Duration


class QoSPolicyKind(IntEnum):
    INVALID = 1 << 0
    DURABILITY = 1 << 1
    DEADLINE = 1 << 2
    LIVELINESS = 1 << 3
    RELIABILITY = 1 << 4
    HISTORY = 1 << 5
    LIFESPAN = 1 << 6
    DEPTH = 1 << 7
    LIVELINESS_LEASE_DURATION = 1 << 8
    AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


def qos_policy_name_from_kind(policy_kind) -> str:
    return QoSPolicyKind(policy_kind).name


class InvalidQoSProfileException(Exception):
    def __init__(self, message: str) -> None:
        Exception.__init__(self, f"Invalid QoSProfile: {message}")


class QoSPolicyEnum(IntEnum):
    @classmethod
    def short_keys(cls) -> list[str]:
        return [k.lower() for k in cls.__members__.keys() if not k.startswith("RMW")]

    @classmethod
    def get_from_short_key(cls, name: str) -> int:
        return cls[name.upper()].value

    @property
    def short_key(self) -> str:
        return self.name.lower()


class HistoryPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy

_DEFAULTS = {"depth": 10, "reliability": ReliabilityPolicy.RELIABLE, "durability": DurabilityPolicy.VOLATILE,
             "lifespan": Duration(), "deadline": Duration(), "liveliness": LivelinessPolicy.SYSTEM_DEFAULT,
             "liveliness_lease_duration": Duration(), "avoid_ros_namespace_conventions": False}


class QoSProfile:
    """A set of QoS policies; history or depth is required (depth alone means KEEP_LAST)."""

    __slots__ = ["_history", "_depth", "_reliability", "_durability", "_lifespan", "_deadline", "_liveliness",
                 "_liveliness_lease_duration", "_avoid_ros_namespace_conventions"]

    def __init__(self, history=None, depth=None, reliability=None, durability=None, lifespan=None, deadline=None,
                 liveliness=None, liveliness_lease_duration=None, avoid_ros_namespace_conventions=None) -> None:
        if history is None:
            if depth is None:
                raise InvalidQoSProfileException("History and/or depth settings are required.")
            history = HistoryPolicy.KEEP_LAST
        self.history = history
        if HistoryPolicy.KEEP_LAST == self.history and depth is None:
            raise InvalidQoSProfileException("History set to KEEP_LAST without a depth setting.")
        given = {"depth": depth, "reliability": reliability, "durability": durability, "lifespan": lifespan,
                 "deadline": deadline, "liveliness": liveliness,
                 "liveliness_lease_duration": liveliness_lease_duration,
                 "avoid_ros_namespace_conventions": avoid_ros_namespace_conventions}
        for key, value in given.items():
            setattr(self, key, _DEFAULTS[key] if value is None else value)

    @property
    def history(self) -> HistoryPolicy:
        return self._history

    @history.setter
    def history(self, value) -> None:
        assert isinstance(value, (HistoryPolicy, int))
        self._history = HistoryPolicy(value)

    @property
    def reliability(self) -> ReliabilityPolicy:
        return self._reliability

    @reliability.setter
    def reliability(self, value) -> None:
        assert isinstance(value, (ReliabilityPolicy, int))
        self._reliability = ReliabilityPolicy(value)

    @property
    def durability(self) -> DurabilityPolicy:
        return self._durability

    @durability.setter
    def durability(self, value) -> None:
        assert isinstance(value, (DurabilityPolicy, int))
        self._durability = DurabilityPolicy(value)

    @property
    def depth(self) -> int:
        return self._depth

    @depth.setter
    def depth(self, value: int) -> None:
        assert isinstance(value, int)
        if self.history == HistoryPolicy.KEEP_LAST and value == 0:
            warnings.warn("A zero depth with KEEP_LAST doesn't make sense; no data could be stored. "
                          "This will be interpreted as SYSTEM_DEFAULT")
        self._depth = value

    @property
    def lifespan(self) -> Duration:
        return self._lifespan

    @lifespan.setter
    def lifespan(self, value: Duration) -> None:
        assert isinstance(value, Duration)
        self._lifespan = value

    @property
    def deadline(self) -> Duration:
        return self._deadline

    @deadline.setter
    def deadline(self, value: Duration) -> None:
        assert isinstance(value, Duration)
        self._deadline = value

    @property
    def liveliness(self) -> LivelinessPolicy:
        return self._liveliness

    @liveliness.setter
    def liveliness(self, value) -> None:
        assert isinstance(value, (LivelinessPolicy, int))
        self._liveliness = LivelinessPolicy(value)

    @property
    def liveliness_lease_duration(self) -> Duration:
        return self._liveliness_lease_duration

    @liveliness_lease_duration.setter
    def liveliness_lease_duration(self, value: Duration) -> None:
        assert isinstance(value, Duration)
        self._liveliness_lease_duration = value

    @property
    def avoid_ros_namespace_conventions(self) -> bool:
        return self._avoid_ros_namespace_conventions

    @avoid_ros_namespace_conventions.setter
    def avoid_ros_namespace_conventions(self, value: bool) -> None:
        assert isinstance(value, bool)
        self._avoid_ros_namespace_conventions = value

    def keeps(self) -> int | None:
        """How many messages a reader keeps: the depth for KEEP_LAST (system default: rmw's 1), None for KEEP_ALL."""
        if self._history == HistoryPolicy.KEEP_ALL:
            return None
        return self._depth if self._depth > 0 else 1

    def __eq__(self, other) -> bool:
        if not isinstance(other, QoSProfile):
            return False
        return all(getattr(self, slot) == getattr(other, slot) for slot in self.__slots__)

    def __str__(self) -> str:
        return f"{type(self).__name__}(%s)" % ", ".join(f"{slot[1:]}=%s" % getattr(self, slot)
                                                       for slot in self.__slots__)


def _profile(history, depth, reliability, durability, liveliness=LivelinessPolicy.SYSTEM_DEFAULT) -> QoSProfile:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return QoSProfile(history=history, depth=depth, reliability=reliability, durability=durability,
                          liveliness=liveliness)


qos_profile_unknown = _profile(HistoryPolicy.UNKNOWN, 0, ReliabilityPolicy.UNKNOWN, DurabilityPolicy.UNKNOWN,
                               LivelinessPolicy.UNKNOWN)
qos_profile_default = _profile(HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_system_default = _profile(HistoryPolicy.SYSTEM_DEFAULT, 0, ReliabilityPolicy.SYSTEM_DEFAULT,
                                      DurabilityPolicy.SYSTEM_DEFAULT)
qos_profile_sensor_data = _profile(HistoryPolicy.KEEP_LAST, 5, ReliabilityPolicy.BEST_EFFORT,
                                   DurabilityPolicy.VOLATILE)
qos_profile_services_default = _profile(HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.RELIABLE,
                                        DurabilityPolicy.VOLATILE)
qos_profile_parameters = _profile(HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE,
                                  DurabilityPolicy.VOLATILE)
qos_profile_parameter_events = _profile(HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE,
                                        DurabilityPolicy.VOLATILE)
qos_profile_best_available = _profile(HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.BEST_AVAILABLE,
                                      DurabilityPolicy.BEST_AVAILABLE, LivelinessPolicy.BEST_AVAILABLE)
qos_profile_action_status_default = _profile(HistoryPolicy.KEEP_LAST, 1, ReliabilityPolicy.RELIABLE,
                                             DurabilityPolicy.TRANSIENT_LOCAL)


class QoSPresetProfiles(Enum):
    UNKNOWN = qos_profile_unknown
    DEFAULT = qos_profile_default
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default
    BEST_AVAILABLE = qos_profile_best_available

    @classmethod
    def short_keys(cls) -> list[str]:
        return [k.lower() for k in cls.__members__.keys()]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        return cls[name.upper()].value


# -- matching (what rmw_fastrtps does at discovery; tests/conformance_ros2/qos_matrix_jazzy.json is the record) ------
# The policies a publisher or subscription ends up with for SYSTEM_DEFAULT (Fast DDS's writer and reader defaults).
_SYSTEM_DEFAULT_OFFERED = (ReliabilityPolicy.RELIABLE, DurabilityPolicy.TRANSIENT_LOCAL)
_SYSTEM_DEFAULT_REQUESTED = (ReliabilityPolicy.BEST_EFFORT, DurabilityPolicy.VOLATILE)


def offered_policies(profile: QoSProfile) -> tuple[ReliabilityPolicy, DurabilityPolicy]:
    """A publisher's (reliability, durability) as it offers them, SYSTEM_DEFAULT resolved."""
    reliability, durability = profile.reliability, profile.durability
    if reliability == ReliabilityPolicy.SYSTEM_DEFAULT:
        reliability = _SYSTEM_DEFAULT_OFFERED[0]
    if durability == DurabilityPolicy.SYSTEM_DEFAULT:
        durability = _SYSTEM_DEFAULT_OFFERED[1]
    return reliability, durability


def requested_policies(profile: QoSProfile, discovered: list[tuple[ReliabilityPolicy, DurabilityPolicy]]
                       ) -> tuple[ReliabilityPolicy, DurabilityPolicy]:
    """A subscription's (reliability, durability) as it requests them, resolved once, when it is created.

    BEST_AVAILABLE asks for the most the publishers discovered by then all offer: RELIABLE and TRANSIENT_LOCAL when
    every one offers it, and also when none has been discovered yet (so a subscription created in a node's
    constructor, before discovery, asks for both and misses a VOLATILE publisher, as on Jazzy).
    """
    reliability, durability = profile.reliability, profile.durability
    if reliability == ReliabilityPolicy.SYSTEM_DEFAULT:
        reliability = _SYSTEM_DEFAULT_REQUESTED[0]
    if durability == DurabilityPolicy.SYSTEM_DEFAULT:
        durability = _SYSTEM_DEFAULT_REQUESTED[1]
    if reliability == ReliabilityPolicy.BEST_AVAILABLE:
        reliability = ReliabilityPolicy.RELIABLE if all(r == ReliabilityPolicy.RELIABLE for r, _ in discovered) \
            else ReliabilityPolicy.BEST_EFFORT
    if durability == DurabilityPolicy.BEST_AVAILABLE:
        durability = DurabilityPolicy.TRANSIENT_LOCAL \
            if all(d == DurabilityPolicy.TRANSIENT_LOCAL for _, d in discovered) else DurabilityPolicy.VOLATILE
    return reliability, durability


def incompatible_policy(offered: tuple[ReliabilityPolicy, DurabilityPolicy],
                        requested: tuple[ReliabilityPolicy, DurabilityPolicy]) -> QoSPolicyKind | None:
    """The last policy in which a publisher offers less than a subscription requests (None: they match), by the
    rule the grader's routing uses too (rosgrade_qos)."""
    last = rosgrade_qos.incompatible(wire_policies(offered), wire_policies(requested))
    return None if last is None else QoSPolicyKind[last]


def wire_policies(policies: tuple[ReliabilityPolicy, DurabilityPolicy]) -> tuple[str, str]:
    """Resolved (reliability, durability) as the grader's routing names them (ADVERTISE/SUBSCRIBE's qos)."""
    return policies[0].name, policies[1].name


def incompatible_qos_warning(topic: str, policy: QoSPolicyKind) -> str:
    """What a subscription's default event handler logs when it discovers a publisher it cannot match."""
    return rosgrade_qos.SUBSCRIPTION_WARNING.format(topic=topic, policy=qos_policy_name_from_kind(policy))
