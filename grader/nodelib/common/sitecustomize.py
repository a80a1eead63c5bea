"""Starts rosgrade's node runtime when the grader launched this process (ROSGRADE_CHANNEL set); otherwise a no-op."""
from __future__ import annotations

import os

if os.environ.get("ROSGRADE_CHANNEL"):
    import rosgrade_node.bootstrap

    rosgrade_node.bootstrap.start(os.environ.pop("ROSGRADE_CHANNEL"))
