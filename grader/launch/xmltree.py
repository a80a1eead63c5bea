"""Parse launch XML into a small element tree that keeps each element's line, for messages that point at it."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

MAX_BYTES = 1 << 20  # a launch file is a few kB; anything larger is refused before parsing


class XmlError(Exception):
    """The file is not well-formed XML; the message carries the line and column."""


@dataclass
class Element:
    """One XML element: tag, attributes in document order, children, its text and the line it starts on."""

    tag: str
    attrs: dict[str, str]
    line: int
    children: list[Element] = field(default_factory=list)
    text: str = ""


def parse(path: Path) -> Element:
    """The root element of the XML file at ``path``."""
    data = path.read_bytes()
    if len(data) > MAX_BYTES:
        raise XmlError(f"the file is {len(data)} bytes; a launch file is expected to be under {MAX_BYTES}")
    parser = expat.ParserCreate()
    stack: list[Element] = []
    roots: list[Element] = []

    def start(tag: str, attrs: dict[str, str]) -> None:
        element = Element(tag, dict(attrs), parser.CurrentLineNumber)
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    def end(_tag: str) -> None:
        stack.pop()

    def text(data: str) -> None:
        if stack:
            stack[-1].text += data

    parser.StartElementHandler, parser.EndElementHandler, parser.CharacterDataHandler = start, end, text
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        raise XmlError(f"{expat.ErrorString(exc.code)}: line {exc.lineno}, column {exc.offset}") from None
    return roots[0]
