"""The recording package's error: one clear line for the CLI, never a library traceback."""
from __future__ import annotations


class RecordingError(Exception):
    """A recording could not be written, read or decoded as its declared type."""
