"""Run with real rclpy and a package built by build_real_interfaces.sh on the path: prints the CDR bytes real rclpy
serializes cdr_values.py's messages to, as JSON {name: hex}."""
from __future__ import annotations

import json

import numpy
from rclpy.serialization import serialize_message

from cdr_values import messages  # noqa: E402 - beside this file
from number_game_interfaces import action, msg, srv

print(json.dumps({name: serialize_message(value).hex()
                  for name, value in messages(msg, srv, action, numpy).items()}, indent=1, sort_keys=True))
