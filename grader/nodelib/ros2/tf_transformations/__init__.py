"""tf_transformations (ROS 2): the same transformations.py port as ROS 1's tf.transformations, same values.

The functions live in ``common/rosgrade_transformations.py``, shared with ROS 1's ``tf.transformations``.
"""
from __future__ import annotations

import rosgrade_transformations as _shared

globals().update({k: v for k, v in vars(_shared).items() if not k.startswith("__")})
