"""Run with rosgrade's ROS 2 import root: installs START's interfaces from a payload file and checks rosgrade's
rosidl runtime against real rclpy's bytes (real_cdr_record.json): prints {name: [decodes equal, ours + padding]}."""
from __future__ import annotations

import json
import sys

import numpy
import rosgrade_interfaces


def main() -> None:
    payload, record = sys.argv[1:3]
    with open(payload) as stream:
        rosgrade_interfaces.install(json.load(stream))
    from rosgrade_rosidl import deserialize, serialize  # noqa: PLC0415 - after the interfaces are installed

    from cdr_values import messages  # noqa: PLC0415 - beside this file
    from number_game_interfaces import action, msg, srv  # noqa: PLC0415
    with open(record) as stream:
        real = {name: bytes.fromhex(text) for name, text in json.load(stream).items()}
    result = {}
    for name, value in messages(msg, srv, action, numpy).items():
        ours = serialize(value)
        # Fast DDS fills alignment gaps and the tail up to 4 bytes with whatever was in its buffer
        result[name] = [deserialize(type(value), real[name]) == value,
                        len(ours) <= len(real[name]) < len(ours) + 4]
    print(json.dumps(result))


if __name__ == "__main__":
    main()
