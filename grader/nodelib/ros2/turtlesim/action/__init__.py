"""turtlesim.action: action classes, built on first use."""
from rosgrade_rosidl._package import lazy_module

__getattr__, __dir__, __all__ = lazy_module(__name__)
