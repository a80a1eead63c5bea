"""turtlesim message classes, built from genpy._msgdefs so every import path yields the same class objects."""
from genpy._builder import export as _export

globals().update(_export(__name__))
__all__ = sorted(name for name in globals() if not name.startswith("_"))
