"""ROS graph-name arithmetic for launch files (joining namespaces, canonical forms), as roslaunch does it."""
from __future__ import annotations

SEP = "/"


def canonical(name: str) -> str:
    """``name`` without repeated or trailing slashes (the root ``/`` stays)."""
    if not name or name == SEP:
        return name
    leading = SEP if name.startswith(SEP) else ""
    return leading + SEP.join(part for part in name.split(SEP) if part)


def global_ns(ns: str) -> str:
    """A namespace in its global form with a trailing slash: ``a/b`` -> ``/a/b/``, ``""`` -> ``/``."""
    ns = canonical(ns)
    if not ns.startswith(SEP):
        ns = SEP + ns
    return ns if ns.endswith(SEP) else ns + SEP


def join(ns: str, name: str) -> str:
    """``name`` inside ``ns``; a global (``/x``) or private (``~x``) name is left as it is."""
    if name.startswith((SEP, "~")) or not ns:
        return name
    return ns + name if ns.endswith(SEP) else ns + SEP + name
