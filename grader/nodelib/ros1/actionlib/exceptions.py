"""actionlib's one exception: a class passed as an action spec that is not a genmsg ``<Name>Action``."""
from __future__ import annotations


class ActionException(Exception):
    """Raised by the clients and servers for a type that is not an action spec."""
