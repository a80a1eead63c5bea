"""actionlib's own test actions (TwoInts, Test, TestRequest: Goal, Result, Feedback and their Action wrappers), as
Debian's python3-actionlib ships them; built from genpy._msgdefs on first use."""
from genpy._builder import lazy_exports as _lazy_exports

__getattr__, __dir__, __all__ = _lazy_exports(__name__)
