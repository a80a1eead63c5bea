"""Puts rosgrade's ROS 1 node library first on sys.path, as a student's node process has it, so `import genpy` is ours."""
from __future__ import annotations

import sys

from grader.nodelib import import_roots

for root in reversed(import_roots("ros1")):
    if str(root) not in sys.path:
        sys.path.insert(0, str(root))
