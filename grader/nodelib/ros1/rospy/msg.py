"""rospy.AnyMsg and the publish(*args, **kwds) to message conversion."""
from __future__ import annotations

import genpy


class AnyMsg(genpy.Message):
    """A message of any type, kept as its serialized bytes (``_buff``)."""

    __slots__ = ["_buff"]
    _type = "*"
    _md5sum = "*"
    _full_text = ""
    _has_header = False
    _slot_types: list[str] = []

    def __init__(self, *args) -> None:
        if args:
            raise genpy.MessageException("AnyMsg does not support constructor arguments")
        self._buff = None

    def serialize(self, buff) -> None:
        if self._buff is None:
            raise genpy.MessageException("AnyMsg is not initialized")
        buff.write(self._buff)

    def deserialize(self, str):  # noqa: A002 - genpy's parameter name
        self._buff = str
        return self


def args_kwds_to_message(data_class: type, args: tuple, kwds: dict):
    """publish()'s argument forms: one message of the right type, or the fields of a new one."""
    if args and kwds:
        raise TypeError("publish() can be called with arguments or keywords, but not both.")
    if kwds:
        return data_class(**kwds)
    if len(args) == 1:
        arg = args[0]
        if getattr(arg, "_md5sum", None) == data_class._md5sum:
            return arg
        # a single message of another type is taken as the first field, and rejected if that does not fit
        if isinstance(arg, genpy.Message) and (not data_class._slot_types
                                                or data_class._slot_types[0] != arg._type):
            expected = data_class._slot_types[0] if data_class._slot_types else data_class._type
            raise TypeError("expected [%s] but got [%s]" % (expected, arg._type))
    return data_class(*args)
