"""Run with a client library's import roots: installs START's interfaces from a payload file as the node runtime
does and prints the example package's behaviour (behaviour.py or behaviour_ros1.py) as JSON.

    python ours.py ros2|ros1 <payload.json> <package>
"""
from __future__ import annotations

import importlib
import io
import json
import sys

import rosgrade_interfaces


def main() -> None:
    flavour, payload, package = sys.argv[1:4]
    with open(payload) as stream:
        rosgrade_interfaces.install(json.load(stream))
    if flavour == "ros2":
        from behaviour import behaviour  # noqa: PLC0415 - beside this file
        modules = {k: importlib.import_module(f"{package}.{k}") for k in ("msg", "srv", "action")}
        print(json.dumps({"behaviour": behaviour(modules)}))
    else:
        from behaviour_ros1 import behaviour  # noqa: PLC0415 - beside this file
        modules = {k: importlib.import_module(f"{package}.{k}") for k in ("msg", "srv")}
        print(json.dumps({"behaviour": behaviour(modules, io)}))


if __name__ == "__main__":
    main()
