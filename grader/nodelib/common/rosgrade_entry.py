"""Starts an ament_python node through its console_scripts entry point, as the wrapper colcon installs does.

``python3 rosgrade_entry.py <package folder> <module>:<function> <executable> [args...]``: the module is imported
under its package name (so ``if __name__ == '__main__'`` blocks do not run, as under `ros2 run`), and the function's
return value is the exit status.
"""
from __future__ import annotations

import importlib
import sys


def main() -> None:
    root, target, executable = sys.argv[1:4]
    sys.argv = [executable, *sys.argv[4:]]
    sys.path[0] = root  # in place of this file's folder, which the node's import path already holds
    module, _, function = target.partition(":")
    sys.exit(getattr(importlib.import_module(module), function)())


if __name__ == "__main__":
    main()
