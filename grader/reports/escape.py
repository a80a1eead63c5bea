"""Escaping per output format, because student-controlled text (tracebacks, log lines, folder and zip member names)
reaches every report: terminal controls, Markdown/HTML, XML and spreadsheet formulas must all arrive inert."""
from __future__ import annotations

import html
import re

# ESC-introduced sequences: CSI (ESC [ ... final), OSC/DCS/SOS/PM/APC strings (ended by BEL or ST, or unterminated),
# and two-character escapes. OSC 52 (clipboard), OSC 8 (hyperlinks) and ESC [2J (clear screen) are among them.
_ESCAPE_SEQUENCE = re.compile(
    r"\x1b\[[0-?]*[ -/]*[@-~]?"
    r"|\x1b[\]PX^_][^\x07\x1b\x9c]*(?:\x07|\x1b\\|\x9c)?"
    r"|\x1b[ -/]*[0-~]?"
    r"|\x9b[0-?]*[ -/]*[@-~]?"
    r"|[\x90\x9d\x98\x9e\x9f][^\x07\x1b\x9c]*(?:\x07|\x1b\\|\x9c)?"
)
# C0 controls except tab and newline, DEL, C1 controls, the bidirectional overrides that make text read
# differently from what it is ("Trojan Source"), and the two non-characters.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\ufffe\uffff]")
# Characters XML 1.0 forbids even as character references (ElementTree would write them and break the file).
_XML_INVALID = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
# Characters that start Markdown syntax anywhere in a line: links and images ([), tables (|), code (`), emphasis (*, ~).
# Underscores stay: GitHub ignores them inside words, and names like move_circle must stay readable in report.md.
_MARKDOWN_INLINE = re.compile(r"([\\`*\[\]|~])")
# Syntax that only counts at the start of a line: headings, quotes, lists, setext underlines, numbered lists.
_MARKDOWN_LINE_START = re.compile(r"^(\s*)([#>+=-]|\d+(?=[.)]))", re.MULTILINE)
# Spreadsheets run a cell starting with these as a formula (=HYPERLINK(...), +cmd|..., @SUM, -2+3).
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r", "\n", "＝", "＋", "－", "＠")


def plain(text: str) -> str:
    """Text without terminal escape sequences or control characters; tabs and newlines are kept."""
    return _CONTROL.sub("", _ESCAPE_SEQUENCE.sub("", text.replace("\r\n", "\n")))


def one_line(text: str) -> str:
    """Plain text on one line (newlines and tabs become spaces): for a console cell or an XML attribute."""
    return " ".join(plain(text).split())


def markdown(text: str, line_start: bool = True) -> str:
    """Plain text that Markdown (GitHub, Gradescope `md`) shows literally: no links, images, tags or tables.

    ``line_start=False`` for text that follows other text on its line: its first line cannot start a block.
    """
    escaped = html.escape(plain(text), quote=False)  # < > & become entities: no tags, no autolinks
    escaped = _MARKDOWN_INLINE.sub(r"\\\1", escaped)
    first, newline, rest = escaped.partition("\n")
    if line_start:
        return _escape_line_starts(escaped)
    return first + newline + _escape_line_starts(rest)


def _escape_line_starts(text: str) -> str:
    return _MARKDOWN_LINE_START.sub(lambda m: f"{m.group(1)}\\{m.group(2)}" if not m.group(2)[0].isdigit()
                                    else f"{m.group(1)}{m.group(2)}\\", text)


def markdown_cell(text: str) -> str:
    """Text for one Markdown table cell: escaped, with line breaks as <br> so the row stays one row."""
    return "<br>".join(markdown(line, line_start=False) for line in plain(text).split("\n"))


def html_text(text: str) -> str:
    """Text for HTML content or attributes."""
    return html.escape(xml(text), quote=True)


def xml(text: str) -> str:
    """Plain text with every character XML 1.0 cannot hold removed (ElementTree does the quoting)."""
    return _XML_INVALID.sub("", plain(text))


def csv_cell(value: object) -> object:
    """A grades.csv cell: text that a spreadsheet would run as a formula gets a leading apostrophe; numbers stay."""
    if not isinstance(value, str):
        return value
    text = plain(value)
    return "'" + text if text.startswith(_FORMULA_START) else text
