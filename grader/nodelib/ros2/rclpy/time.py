"""rclpy.time.Time: a non-negative point in integer nanoseconds of one clock type, as real rclpy."""
from __future__ import annotations

from .clock_type import ClockType
from .constants import S_TO_NS
from .duration import Duration


class Time:
    """A point in time; only comparable with time points of the same clock type."""

    __slots__ = ("_nanoseconds", "_clock_type")

    def __init__(self, *, seconds: int | float = 0, nanoseconds: int = 0,
                 clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        if seconds < 0:
            raise ValueError("Seconds value must not be negative")
        if nanoseconds < 0:
            raise ValueError("Nanoseconds value must not be negative")
        total = int(seconds * S_TO_NS) + int(nanoseconds)
        if total >= 2**63:
            raise OverflowError("Total nanoseconds value is too large to store in C time point.")
        self._nanoseconds = total
        self._clock_type = clock_type

    @property
    def nanoseconds(self) -> int:
        return self._nanoseconds

    def seconds_nanoseconds(self) -> tuple[int, int]:
        return (self._nanoseconds // S_TO_NS, self._nanoseconds % S_TO_NS)

    @property
    def clock_type(self) -> ClockType:
        return self._clock_type

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self.nanoseconds}, clock_type={self.clock_type.name})"

    def __hash__(self) -> int:
        return hash((self._nanoseconds, self._clock_type))

    def __add__(self, other):
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self.nanoseconds + other.nanoseconds, clock_type=self.clock_type)
            except OverflowError as e:
                raise OverflowError("Addition leads to overflow in C storage.") from e
        return NotImplemented

    def __radd__(self, other):
        return self.__add__(other)

    def __sub__(self, other):
        if isinstance(other, Time):
            if self.clock_type != other.clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self.nanoseconds - other.nanoseconds)
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self.nanoseconds - other.nanoseconds, clock_type=self.clock_type)
            except ValueError as e:
                raise ValueError("Subtraction leads to negative time.") from e
        return NotImplemented

    def _check(self, other: Time) -> None:
        if self.clock_type != other.clock_type:
            raise TypeError("Can't compare times with different clock types")

    def __eq__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self.nanoseconds == other.nanoseconds
        return NotImplemented

    def __ne__(self, other):
        if isinstance(other, Time):
            return not self.__eq__(other)
        return NotImplemented

    def __lt__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self.nanoseconds < other.nanoseconds
        return NotImplemented

    def __le__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self.nanoseconds <= other.nanoseconds
        return NotImplemented

    def __gt__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self.nanoseconds > other.nanoseconds
        return NotImplemented

    def __ge__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self.nanoseconds >= other.nanoseconds
        return NotImplemented

    def to_msg(self):
        """The time as a builtin_interfaces.msg.Time."""
        import builtin_interfaces.msg
        seconds, nanoseconds = self.seconds_nanoseconds()
        return builtin_interfaces.msg.Time(sec=seconds, nanosec=nanoseconds)

    @classmethod
    def from_msg(cls, msg, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        import builtin_interfaces.msg
        if not isinstance(msg, builtin_interfaces.msg.Time):
            raise TypeError("Must pass a builtin_interfaces.msg.Time object")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)
