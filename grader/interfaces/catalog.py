"""One type catalog per run: the built-in definitions plus the submission's own, and what its nodes are given.

``catalog_for`` makes the grader's catalog (codecs, hashes, MCAP schemas) of a run; ``node_payload`` the same types
as the data a node's client library builds its classes from (START's ``interfaces``), so both sides share one
parse (rosbags') and one set of hashes.
"""
from __future__ import annotations

import json

from rosbags.typesys.base import Nodetype
from rosbags.typesys.store import Typestore

from grader.interfaces.derived import action_types, ros1_service_md5, service_types
from grader.interfaces.reading import InterfaceSet, TypeDef
from grader.nodelib.ros1.genpy import _msgdefs as ros1_node_defs
from grader.nodelib.ros2.rosgrade_rosidl import _defs as ros2_node_defs
from grader.recording.messages import MessageCatalog, default_catalog
from grader.recording.ros2_messages import Ros2Catalog, ros2_catalog

MAX_PAYLOAD_BYTES = 160 * 1024  # START's JSON is capped at 256 KiB with the parameters beside it


class CatalogError(Exception):
    """An interface set of another ROS version than the run's."""


def builtin_types(flavour: str) -> list[str]:
    """The type names (rosbags' spelling) a run of ``flavour`` knows without the submission's."""
    catalog = ros2_catalog() if flavour == "ros2" else default_catalog()
    return list(catalog.typestore.fielddefs)


def _ros2_extra(interfaces: InterfaceSet) -> tuple[dict[str, TypeDef], list[str]]:
    types = dict(interfaces.types)
    services = list(interfaces.services)
    for service, (request, response) in interfaces.services.items():
        types.update(service_types(service, types[request], types[response]))
    for action, (goal, result, feedback) in interfaces.actions.items():
        types.update(action_types(action, types[goal], types[result], types[feedback]))
        services += [f"{action}_SendGoal", f"{action}_GetResult"]
    return types, services


def catalog_for(flavour: str, interfaces: InterfaceSet | None) -> Ros2Catalog | MessageCatalog:
    """The run's catalog: the shared built-in one when the submission has no interfaces of its own."""
    if not interfaces:
        return ros2_catalog() if flavour == "ros2" else default_catalog()
    if interfaces.flavour != flavour:
        raise CatalogError(f"{interfaces.flavour} interfaces cannot serve a {flavour} run")
    if flavour == "ros2":
        types, services = _ros2_extra(interfaces)
        return Ros2Catalog(types, services)
    catalog = MessageCatalog(interfaces.types)
    md5s = {_ros1_name(service): ros1_service_md5(catalog.typestore, request, response)
            for service, (request, response) in interfaces.services.items()}
    return MessageCatalog(interfaces.types, md5s)


def _ros1_name(name: str) -> str:
    package, _, short = name.split("/")
    return f"{package}/{short}"


def _dependencies(store: Typestore, names: list[str]) -> list[str]:
    """``names`` and every type they contain, each once, in first-seen order."""
    seen: dict[str, None] = {}
    stack = list(reversed(names))
    while stack:
        name = stack.pop()
        if name in seen or name not in store.fielddefs:
            continue
        seen[name] = None
        for _, (node, detail) in store.fielddefs[name][1]:
            if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
                node, detail = detail[0]
            if node == Nodetype.NAME:
                stack.append(detail)
    return list(seen)


def _field(name: str, desc: tuple, defaults: dict) -> list:
    """(name, type, kind, size, string bound, default) as the node's rosidl runtime reads a field."""
    node, detail = desc
    kind, size = 0, 0
    if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
        kind = 1 if node == Nodetype.ARRAY else 2
        (node, detail), size = detail
    if node == Nodetype.NAME:
        return [name, detail, kind, size, 0, defaults.get(name)]
    base, bound = detail
    return [name, base, kind, size, bound, defaults.get(name)]


def ros2_entry(catalog: Ros2Catalog, name: str, defaults: dict) -> list:
    """A type as the node's definition table holds it: [fields, constants, RIHS01]."""
    consts, fields = catalog.typestore.fielddefs[name]
    return [[_field(fname, desc, defaults) for fname, desc in fields],
            [[cname, ctype, value] for cname, ctype, value in consts], catalog.md5sum(name)]


def _ros2_payload(interfaces: InterfaceSet) -> dict:
    types, services = _ros2_extra(interfaces)
    catalog = Ros2Catalog(types, services)
    structs = set(services) | set(interfaces.actions)
    wanted = [name for name in types if name not in structs]
    messages = {name: ros2_entry(catalog, name, interfaces.defaults.get(name, {}))
                for name in _dependencies(catalog.typestore, wanted) if name not in ros2_node_defs.MESSAGES}
    return {"messages": messages, "services": {name: catalog.service_md5sum(name) for name in services},
            "actions": {name: catalog.md5sum(name) for name in interfaces.actions}}


def _ros1_payload(interfaces: InterfaceSet) -> dict:
    store = MessageCatalog(interfaces.types).typestore
    parts = {name for pair in interfaces.services.values() for name in pair}
    wanted = [name for name in interfaces.types if name not in parts]
    service_parts = [name for pair in interfaces.services.values() for name in pair]
    messages = {_ros1_name(name): store.gendefhash(name, {}, 1)[0]
                for name in _dependencies(store, wanted + service_parts)
                if name not in parts and _ros1_name(name) not in ros1_node_defs.MESSAGES
                and not name.startswith("builtin_interfaces/")}
    services = {_ros1_name(service): "---\n".join(store.gendefhash(part, {}, 1)[0] for part in (request, response))
                for service, (request, response) in interfaces.services.items()}
    return {"messages": messages, "services": services}


def node_payload(interfaces: InterfaceSet | None) -> dict | None:
    """What a node of the run is given at START to build the submission's classes from (None: nothing); the
    interfaces are emptied, with a finding, when it would not fit."""
    if not interfaces:
        return None
    payload = _ros2_payload(interfaces) if interfaces.flavour == "ros2" else _ros1_payload(interfaces)
    size = len(json.dumps(payload, separators=(",", ":")))
    if size > MAX_PAYLOAD_BYTES:
        interfaces.findings.append(f"the submission's interfaces make {size >> 10} KiB of definitions; rosgrade "
                                   f"gives a node at most {MAX_PAYLOAD_BYTES >> 10} KiB, so none were used.")
        interfaces.types.clear()
        interfaces.services.clear()
        interfaces.actions.clear()
        return None
    return payload
