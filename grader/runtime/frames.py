"""One schema per kind of frame a node sends: the channel contract, checked field by field at the grader's edge.

A node's frames are untrusted input. ``parse`` turns a frame into a typed, bounded value or raises FrameError with
one line saying what was wrong; the node link makes that the node's ``protocol_violation`` verdict.
"""
from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, JsonValue, ValidationError, model_validator

from grader.nodelib.common import rosgrade_channel as ch

MAX_ARGV = 256

Handle = Annotated[int, Field(ge=0, lt=1 << 32)]
# Values a student passes through unchanged (queue_size=True, log_level=rospy.DEBUG): informative only, so lax.
LaxInt = Annotated[int | None, Field(strict=False)]
Name = Annotated[str, Field(max_length=ch.MAX_NAME_CHARS)]
Label = Annotated[str, Field(max_length=ch.MAX_LABEL_CHARS)]
FilePath = Annotated[str, Field(max_length=ch.MAX_PATH_CHARS)]
Message = Annotated[str, Field(max_length=ch.MAX_MESSAGE_CHARS)]
# A ROS 1 md5sum, a ROS 2 (Jazzy) RIHS01 type hash, or "*" (rospy's any-type wildcard).
TypeHash = Annotated[str, Field(pattern=r"^[0-9a-f]{32}$|^RIHS01_[0-9a-f]{64}$|^\*$")]


class FrameError(Exception):
    """A frame does not match its kind's schema."""


class _Frame(BaseModel):
    # strict: no "1" for 1 or 1.0 for 1; forbid: a field the protocol does not define is a violation too.
    model_config = ConfigDict(strict=True, extra="forbid", frozen=True)


class Hello(_Frame):
    protocol: int
    pid: int
    argv: Annotated[list[FilePath], Field(max_length=MAX_ARGV)]


class Init(_Frame):
    name: Name
    anonymous: bool
    log_level: LaxInt
    disable_signals: bool


class Register(_Frame):
    """ADVERTISE and SUBSCRIBE."""

    id: Handle
    topic: Name
    type: Name
    md5sum: TypeHash
    queue_size: LaxInt
    latch: bool
    qos: list[Name] | None = None  # ROS 2: resolved [reliability, durability] offered or requested (rosgrade_qos)


class Unregister(_Frame):
    id: Handle


class Log(_Frame):
    level: int
    msg: str
    name: Name
    file: FilePath
    function: Label
    line: Annotated[int, Field(ge=0)]


class TracebackFrame(_Frame):
    file: FilePath
    line: int | None
    function: Label
    text: Message


class ExceptionReport(_Frame):
    type: Label
    message: Message
    frames: Annotated[list[TracebackFrame], Field(max_length=ch.MAX_TRACEBACK_FRAMES)]
    where: Annotated[str, Field(max_length=40)]


class Wait(_Frame):
    wake_ns: Annotated[int, Field(ge=0)] | None
    busy: bool = False


class Call(_Frame):
    """The JSON header of a CALL (the request's bytes follow it): the answer comes in a later BATCH on the client's
    handle ``id``, for its call number ``seq``. ``probe``: only ask whether the service is served, with no request
    (``wait_for_service``, as rospy's probe connection), answered at once by a REPLY."""

    service: Name
    type: Name  # "*" with md5sum "*" in a probe, which names no srv type
    md5sum: TypeHash
    probe: bool
    id: Handle
    seq: Handle


class Serve(_Frame):
    """SERVE: the node offers ``service`` of srv ``type`` under its handle ``id``; UNREGISTER withdraws it."""

    id: Handle
    service: Name
    type: Name
    md5sum: TypeHash


class Respond(_Frame):
    """The JSON header of a RESPOND (the response's bytes follow it when ``ok``): the node's answer to request
    ``seq`` delivered on its server handle ``id``; ``failed`` with the server's text (rospy's handler raised)."""

    id: Handle
    seq: Handle
    status: Literal["ok", "failed"]
    error: Annotated[str, Field(max_length=ch.MAX_MESSAGE_CHARS)]


class Param(_Frame):
    """A change to the run's parameter server: ``set`` a value (a dict sets a namespace) or ``delete`` a name. The
    value is what XML-RPC carries, so never null; its size and nesting are bounded by the frame's."""

    op: Literal["set", "delete"]
    name: Name
    value: JsonValue = None

    @model_validator(mode="after")
    def _value_fits_op(self) -> Param:
        if (self.op == ch.PARAM_SET) != (self.value is not None):
            raise ValueError("a set needs a value that is not null, a delete takes none")
        return self


SCHEMAS: dict[int, type[_Frame]] = {
    ch.HELLO: Hello, ch.INIT: Init, ch.ADVERTISE: Register, ch.SUBSCRIBE: Register, ch.UNREGISTER: Unregister,
    ch.LOG: Log, ch.EXCEPTION: ExceptionReport, ch.WAIT: Wait, ch.CALL: Call, ch.PARAM: Param, ch.SERVE: Serve,
    ch.RESPOND: Respond,
}


def parse(kind: int, payload: bytes) -> _Frame:
    """The frame's value, validated against its kind's schema; FrameError (one line) otherwise."""
    label = ch.KIND_NAMES.get(kind, str(kind))
    if len(payload) > ch.MAX_JSON_BYTES:
        raise FrameError(f"{label} frame of {len(payload)} bytes exceeds {ch.MAX_JSON_BYTES}")
    try:
        # pydantic's JSON parser bounds nesting depth itself (no RecursionError from 100k nested arrays).
        return SCHEMAS[kind].model_validate_json(payload)
    except ValidationError as exc:
        first = exc.errors(include_url=False, include_input=False)[0]
        where = ".".join(str(part) for part in first["loc"])
        field = f" field {where!r}" if where else ""
        problems = f" (and {exc.error_count() - 1} more)" if exc.error_count() > 1 else ""
        raise FrameError(f"{label} frame{field}: {first['msg'][:120]}{problems}") from None
