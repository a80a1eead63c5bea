"""Node-side runtime of rosgrade: the lockstep scheduler, the channel link and the process patches (stdlib only).

``sitecustomize`` starts it when ``ROSGRADE_CHANNEL`` is set; ``rospy`` reaches it through ``rosgrade_node.runtime``.
"""
