"""ROS 2 name rules: node, namespace and topic validation (rmw's messages) and topic expansion with remaps."""
from __future__ import annotations

import re

from .exceptions import (InvalidNamespaceException, InvalidNodeNameException, InvalidServiceNameException,
                         InvalidTopicNameException)

_NODE_CHAR = re.compile(r"[^A-Za-z0-9_]")
_TOPIC_CHAR = re.compile(r"[^A-Za-z0-9_~{}/]")


def validate_node_name(node_name: str) -> bool:
    if not node_name:
        raise InvalidNodeNameException(node_name, "node name must not be empty", 0)
    if m := _NODE_CHAR.search(node_name):
        raise InvalidNodeNameException(
            node_name, "node name must not contain characters other than alphanumerics or '_'", m.start())
    if node_name[0].isdigit():
        raise InvalidNodeNameException(node_name, "node name must not start with a number", 0)
    if len(node_name) > 255:
        raise InvalidNodeNameException(node_name, "node name length should not exceed 255", 254)
    return True


def validate_namespace(namespace: str) -> bool:
    if not namespace:
        raise InvalidNamespaceException(namespace, "namespace must not be empty", 0)
    if not namespace.startswith("/"):
        raise InvalidNamespaceException(namespace, "namespace must be absolute, it must lead with a '/'", 0)
    if namespace != "/" and namespace.endswith("/"):
        raise InvalidNamespaceException(namespace, "namespace must not end with a forward slash",
                                        len(namespace) - 1)
    if m := re.search(r"[^A-Za-z0-9_/]", namespace):
        raise InvalidNamespaceException(
            namespace, "namespace must not contain characters other than alphanumerics, '_', or '/'", m.start())
    if (i := namespace.find("//")) >= 0:
        raise InvalidNamespaceException(namespace, "namespace must not contain repeated forward slashes", i + 1)
    for m in re.finditer(r"/([0-9])", namespace):
        raise InvalidNamespaceException(namespace, "namespace must not have a token that starts with a number",
                                        m.start(1))
    return True


def validate_topic_name(name: str, *, is_service: bool = False) -> bool:
    exc = InvalidServiceNameException if is_service else InvalidTopicNameException
    kind = "service name" if is_service else "topic name"
    if not name:
        raise exc(name, f"{kind} must not be empty", 0)
    if m := _TOPIC_CHAR.search(name):
        raise exc(name, f"{kind} must not contain characters other than alphanumerics, '_', '~', '{{', or '}}'",
                  m.start())
    if name[0].isdigit():
        raise exc(name, f"{kind} must not start with a number", 0)
    if name.endswith("/"):
        raise exc(name, f"{kind} must not end with a forward slash", len(name) - 1)
    if (i := name.find("//")) >= 0:
        raise exc(name, f"{kind} must not contain repeated forward slashes", i + 1)
    if "~" in name[1:]:
        raise exc(name, f"{kind} must not contain a tilde (~) except as the first character", name.index("~", 1))
    if name.startswith("~") and len(name) > 1 and name[1] != "/":
        raise exc(name, f"{kind} must have a '/' after a tilde (~)", 1)
    return True


def validate_full_topic_name(name: str, *, is_service: bool = False) -> bool:
    exc = InvalidServiceNameException if is_service else InvalidTopicNameException
    kind = "service name" if is_service else "topic name"
    if not name.startswith("/"):
        raise exc(name, f"{kind} must be absolute, it must lead with a '/'", 0)
    if "{" in name or "}" in name or "~" in name:
        raise exc(name, f"{kind} must not contain characters other than alphanumerics, '_', or '/'",
                  min(i for i in (name.find("{"), name.find("}"), name.find("~")) if i >= 0))
    for m in re.finditer(r"/([0-9])", name):
        raise exc(name, f"{kind} must not have a token that starts with a number", m.start(1))
    return validate_topic_name(name, is_service=is_service)


def expand_topic_name(topic_name: str, node_name: str, node_namespace: str) -> str:
    """rcl's expansion: '~' is the node's private namespace, relative names go under the node's namespace."""
    ns = node_namespace if node_namespace else "/"
    name = topic_name.replace("{node}", node_name).replace("{ns}", ns).replace("{namespace}", ns)
    if name.startswith("~"):
        private = (ns.rstrip("/") + "/" + node_name)
        name = private + name[1:]
    elif not name.startswith("/"):
        name = ns.rstrip("/") + "/" + name
    return name


def fully_qualified(node_name: str, namespace: str) -> str:
    return namespace.rstrip("/") + "/" + node_name


def logger_name(node_name: str, namespace: str) -> str:
    """The node's logger: namespace tokens and name joined by dots, without the leading slash."""
    return ".".join([t for t in namespace.split("/") if t] + [node_name])
