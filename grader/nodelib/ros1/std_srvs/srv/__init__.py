"""std_srvs service classes (Name, NameRequest, NameResponse), built from genpy._msgdefs."""
from genpy._builder import lazy_exports as _lazy_exports

__getattr__, __dir__, __all__ = _lazy_exports(__name__)
