"""Probe: without init_node, a SHUTDOWN is a plain KeyboardInterrupt raised in the sleeping main thread."""
import time

print("sleeping")
time.sleep(5)
print("not reached")
