"""rosgrade's roslib: ``roslib.load_manifest(pkg)`` as older tutorials call it (a no-op for catkin packages)."""
from __future__ import annotations

__all__ = ["load_manifest"]

_loaded: set[str] = set()


def load_manifest(package_name, bootstrap_version="0.7") -> None:
    """Check that ``package_name`` exists (rospkg.ResourceNotFound otherwise); catkin puts its Python on the path."""
    if package_name in _loaded:
        return
    import rospkg
    rospkg.RosPack().get_path(package_name)
    _loaded.add(package_name)
