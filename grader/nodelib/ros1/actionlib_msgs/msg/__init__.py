"""actionlib_msgs message classes, built from genpy._msgdefs on first use."""
from genpy._builder import lazy_exports as _lazy_exports

__getattr__, __dir__, __all__ = _lazy_exports(__name__)
