"""rosgrade's simulated world: robot profiles, MuJoCo physics, base drivers, odometry and the clock."""
from __future__ import annotations
