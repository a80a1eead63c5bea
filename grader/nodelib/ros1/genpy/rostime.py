"""genpy.Time and genpy.Duration: ROS 1 time values with genpy 0.6's exact arithmetic, normalisation and errors."""
from __future__ import annotations

import math
import numbers

_NS = 1_000_000_000


def _canon(secs, nsecs):
    """Carry nsecs into secs so that 0 <= nsecs < 1e9 (keeps int/float types as genpy does)."""
    while nsecs >= _NS:
        secs += 1
        nsecs -= _NS
    while nsecs < 0:
        secs -= 1
        nsecs += _NS
    return secs, nsecs


def _split_float(value):
    """secs, nsecs of a float seconds value, truncating the nanoseconds like genpy's from_sec."""
    secs = int(math.floor(value))
    return secs, int((value - secs) * 1e9)


class TVal:
    """Shared base of Time and Duration: a (secs, nsecs) pair kept canonical."""

    __slots__ = ["secs", "nsecs"]
    _slot_types = ["int32", "int32"]

    def __init__(self, secs=0, nsecs=0):
        if type(secs) is int and type(nsecs) is int and 0 <= nsecs < _NS:  # already canonical: most values a node makes
            self.secs, self.nsecs = secs, nsecs
            return
        if type(secs) is not int and not isinstance(secs, numbers.Integral):  # an ABC check only when not an int
            # a float (or anything else) is taken as seconds; genpy computes int() first, then the fraction
            if nsecs != 0:
                raise ValueError("if secs is a float, nsecs cannot be set")
            whole = int(secs)
            nsecs = int((secs - whole) * 1e9)
            secs = whole
        else:
            secs, nsecs = int(secs), int(nsecs)  # Time(0, 5e8) keeps integer fields
        self.secs, self.nsecs = _canon(secs, nsecs)

    @classmethod
    def from_sec(cls, float_secs):
        """A value from float seconds; the nanoseconds are truncated, not rounded."""
        secs, nsecs = _split_float(float_secs)
        return cls(secs, nsecs)

    def is_zero(self) -> bool:
        return self.secs == 0 and self.nsecs == 0

    def set(self, secs, nsecs) -> None:
        self.secs = secs
        self.nsecs = nsecs

    def canon(self) -> None:
        self.secs, self.nsecs = _canon(self.secs, self.nsecs)

    def to_sec(self) -> float:
        return float(self.secs) + float(self.nsecs) / 1e9

    def to_nsec(self) -> int:
        return self.secs * _NS + self.nsecs

    def __hash__(self):
        return hash((self.secs, self.nsecs))

    def __str__(self):
        return str(self.to_nsec())

    def __bool__(self):
        return not self.is_zero()

    __nonzero__ = __bool__

    def __getstate__(self):
        return [self.secs, self.nsecs]

    def __setstate__(self, state):
        self.secs, self.nsecs = state

    def __cmp__(self, other):
        if not isinstance(other, TVal):
            raise TypeError("cannot compare to non-Time")
        a, b = self.to_nsec(), other.to_nsec()
        return (a > b) - (a < b)

    def _comparable(self, other) -> bool:
        """Ordering is defined only between values of the same kind (Time with Time, Duration with Duration)."""
        return isinstance(other, self._kind())

    def __lt__(self, other):
        return self.to_nsec() < other.to_nsec() if self._comparable(other) else NotImplemented

    def __le__(self, other):
        return self.to_nsec() <= other.to_nsec() if self._comparable(other) else NotImplemented

    def __gt__(self, other):
        return self.to_nsec() > other.to_nsec() if self._comparable(other) else NotImplemented

    def __ge__(self, other):
        return self.to_nsec() >= other.to_nsec() if self._comparable(other) else NotImplemented

    def __eq__(self, other):
        if not self._comparable(other):
            return False
        return self.secs == other.secs and self.nsecs == other.nsecs

    def __ne__(self, other):
        return not self.__eq__(other)

    def _kind(self) -> type:
        raise NotImplementedError


class Time(TVal):
    """A point in time; never negative."""

    __slots__ = []

    def __init__(self, secs=0, nsecs=0):
        TVal.__init__(self, secs, nsecs)
        if self.secs < 0:
            raise TypeError("time values must be positive")

    def _kind(self) -> type:
        return Time

    def __repr__(self):
        return "genpy.Time[%d]" % self.to_nsec()

    def to_time(self) -> float:
        return self.to_sec()

    def __add__(self, other):
        if not isinstance(other, Duration):
            return NotImplemented
        return self.__class__(self.secs + other.secs, self.nsecs + other.nsecs)

    __radd__ = __add__

    def __sub__(self, other):
        if isinstance(other, Time):
            return Duration(self.secs - other.secs, self.nsecs - other.nsecs)
        if isinstance(other, Duration):
            return self.__class__(self.secs - other.secs, self.nsecs - other.nsecs)
        return NotImplemented

    __hash__ = TVal.__hash__


class Duration(TVal):
    """A signed span of time; nsecs stays non-negative, so -0.5 s is (-1, 500000000)."""

    __slots__ = []

    def _kind(self) -> type:
        return Duration

    def __repr__(self):
        return "genpy.Duration[%d]" % self.to_nsec()

    def __neg__(self):
        return self.__class__(-self.secs, -self.nsecs)

    def __abs__(self):
        return self if self.secs >= 0 else -self

    def __add__(self, other):
        if isinstance(other, Time):
            return other.__add__(self)
        if isinstance(other, Duration):
            return self.__class__(self.secs + other.secs, self.nsecs + other.nsecs)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other):
        if not isinstance(other, Duration):
            return NotImplemented
        return self.__class__(self.secs - other.secs, self.nsecs - other.nsecs)

    def __mul__(self, val):
        if isinstance(val, numbers.Integral):
            return self.__class__(self.secs * val, self.nsecs * val)
        if isinstance(val, numbers.Real):
            return self.__class__.from_sec(self.to_sec() * val)
        return NotImplemented

    __rmul__ = __mul__

    def __floordiv__(self, val):
        if isinstance(val, numbers.Integral) or isinstance(val, numbers.Real):
            return self.__class__.from_sec(self.to_sec() // val)
        if isinstance(val, Duration):
            return int(self.to_sec() // val.to_sec())
        return NotImplemented

    def __truediv__(self, val):
        if isinstance(val, numbers.Integral) or isinstance(val, numbers.Real):
            return self.__class__.from_sec(self.to_sec() / val)
        if isinstance(val, Duration):
            return self.to_sec() / val.to_sec()
        return NotImplemented

    __div__ = __truediv__

    def __mod__(self, val):
        if not isinstance(val, Duration):
            return NotImplemented
        return self.__class__.from_sec(self.to_sec() % val.to_sec())

    def __divmod__(self, val):
        if not isinstance(val, Duration):
            return NotImplemented
        return self // val, self % val

    __hash__ = TVal.__hash__
