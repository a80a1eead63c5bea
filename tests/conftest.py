"""What every test needs of the process that runs the suite."""
from __future__ import annotations

import signal

# A suite started in the background by a non-interactive shell (`cmd &`, nohup) inherits SIGINT ignored, and so
# would every process it starts: the tests of Ctrl+C (the batch's, rclpy's and rospy's real ones) need it as an
# interactive run has it.
signal.signal(signal.SIGINT, signal.default_int_handler)
