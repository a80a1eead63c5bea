"""nav_msgs service classes (Name, NameRequest, NameResponse), built from genpy._msgdefs."""
from genpy._builder import export as _export

globals().update(_export(__name__))
__all__ = sorted(name for name in globals() if not name.startswith("_"))
