"""The types rosidl and genmsg derive from a service or action, as rosbags type definitions, and ROS 1 md5 texts.

ROS 2 (rosidl_generator_type_description): a service ``S`` is described as a struct of ``request_message``,
``response_message`` and ``event_message`` (``S_Event``: info, request[<=1], response[<=1]), which its RIHS01 hash
covers; an action ``A`` as a struct of its Goal, Result and Feedback, its ``SendGoal`` and ``GetResult`` services
and its ``FeedbackMessage``, each carrying the goal's UUID as rcl_action puts it on the wire.
"""
from __future__ import annotations

from hashlib import md5

from rosbags.typesys.base import Nodetype
from rosbags.typesys.store import Typestore

TypeDef = tuple[list, list]
UUID = "unique_identifier_msgs/msg/UUID"
TIME = "builtin_interfaces/msg/Time"
EVENT_INFO = "service_msgs/msg/ServiceEventInfo"
EMPTY_MEMBER = "structure_needs_at_least_one_member"


def _name(type_name: str) -> tuple:
    return (Nodetype.NAME, type_name)


def _base(primitive: str) -> tuple:
    return (Nodetype.BASE, (primitive, 0))


def _filled(typedef: TypeDef) -> TypeDef:
    """rosidl gives a struct without fields one uint8 member, on the wire and in its hash."""
    return (typedef[0], typedef[1] or [(EMPTY_MEMBER, _base("uint8"))])


def service_types(service: str, request: TypeDef, response: TypeDef) -> dict[str, TypeDef]:
    """``S_Request``, ``S_Response``, ``S_Event`` and the struct ``S`` its hash is taken of."""
    return {
        f"{service}_Request": _filled(request),
        f"{service}_Response": _filled(response),
        f"{service}_Event": ([], [
            ("info", _name(EVENT_INFO)),
            ("request", (Nodetype.SEQUENCE, (_name(f"{service}_Request"), 1))),
            ("response", (Nodetype.SEQUENCE, (_name(f"{service}_Response"), 1))),
        ]),
        service: ([], [
            ("request_message", _name(f"{service}_Request")),
            ("response_message", _name(f"{service}_Response")),
            ("event_message", _name(f"{service}_Event")),
        ]),
    }


def action_types(action: str, goal: TypeDef, result: TypeDef, feedback: TypeDef) -> dict[str, TypeDef]:
    """The action's three messages, its SendGoal and GetResult services, FeedbackMessage and the struct ``A``."""
    types = {f"{action}_Goal": _filled(goal), f"{action}_Result": _filled(result),
             f"{action}_Feedback": _filled(feedback)}
    types.update(service_types(f"{action}_SendGoal",
                               ([], [("goal_id", _name(UUID)), ("goal", _name(f"{action}_Goal"))]),
                               ([], [("accepted", _base("bool")), ("stamp", _name(TIME))])))
    types.update(service_types(f"{action}_GetResult", ([], [("goal_id", _name(UUID))]),
                               ([], [("status", _base("int8")), ("result", _name(f"{action}_Result"))])))
    types[f"{action}_FeedbackMessage"] = ([], [("goal_id", _name(UUID)), ("feedback", _name(f"{action}_Feedback"))])
    types[action] = ([], [
        ("goal", _name(f"{action}_Goal")),
        ("result", _name(f"{action}_Result")),
        ("feedback", _name(f"{action}_Feedback")),
        ("send_goal_service", _name(f"{action}_SendGoal")),
        ("get_result_service", _name(f"{action}_GetResult")),
        ("feedback_message", _name(f"{action}_FeedbackMessage")),
    ])
    return types


def ros1_action_types(package: str, action: str) -> dict[str, TypeDef]:
    """The four messages genmsg wraps an action's Goal, Result and Feedback in, as actionlib sends them."""
    name = f"{package}/msg/{action}"
    header, status = _name("std_msgs/msg/Header"), _name("actionlib_msgs/msg/GoalStatus")
    return {
        f"{name}ActionGoal": ([], [("header", header), ("goal_id", _name("actionlib_msgs/msg/GoalID")),
                                   ("goal", _name(f"{name}Goal"))]),
        f"{name}ActionResult": ([], [("header", header), ("status", status), ("result", _name(f"{name}Result"))]),
        f"{name}ActionFeedback": ([], [("header", header), ("status", status),
                                       ("feedback", _name(f"{name}Feedback"))]),
        f"{name}Action": ([], [("action_goal", _name(f"{name}ActionGoal")),
                               ("action_result", _name(f"{name}ActionResult")),
                               ("action_feedback", _name(f"{name}ActionFeedback"))]),
    }


def ros1_md5_text(store: Typestore, type_name: str) -> str:
    """genmsg's md5 text of a type in ``store``: constants, then fields with nested types replaced by their md5."""
    consts, fields = store.fielddefs[type_name]
    lines = [f"{ctype} {cname}={value}" for cname, ctype, value in consts]
    times = {"builtin_interfaces/msg/Time": "time", "builtin_interfaces/msg/Duration": "duration"}
    for fname, (node, detail) in fields:
        suffix = ""
        if node in (Nodetype.ARRAY, Nodetype.SEQUENCE):
            (node, detail), count = detail
            suffix = f"[{count or ''}]"
        if node == Nodetype.BASE:
            lines.append(f"{detail[0]}{suffix} {fname}")
        elif detail in times:
            lines.append(f"{times[detail]}{suffix} {fname}")
        else:
            lines.append(f"{store.gendefhash(detail, {}, 1)[1]} {fname}")
    return "\n".join(lines)


def ros1_service_md5(store: Typestore, request: str, response: str) -> str:
    """genmsg's md5 of a service: of its request's md5 text followed by its response's."""
    return md5((ros1_md5_text(store, request) + ros1_md5_text(store, response)).encode()).hexdigest()
