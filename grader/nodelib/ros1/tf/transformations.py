"""tf.transformations: homogeneous-transform and quaternion helpers with real tf 1.13's conventions and values.

The functions live in ``common/rosgrade_transformations.py``, shared with ROS 2's ``tf_transformations``; this module
carries every name of it (private ones included), as the module itself did.
"""
from __future__ import annotations

import rosgrade_transformations as _shared

globals().update({k: v for k, v in vars(_shared).items() if not k.startswith("__")})
